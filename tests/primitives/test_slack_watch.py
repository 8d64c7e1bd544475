from tautwire.primitives.slack_watch import SlackWatch


def test_slack_only_after_the_duration_and_reset_by_tension() -> None:
    w = SlackWatch(1.0)
    assert not w.update(0.0, 0.1, 2.0)
    assert not w.update(1.0, 0.1, 2.0)
    assert w.update(1.01, 0.1, 2.0)
    assert not w.update(1.02, 1.0, 2.0)  # taut again: the spell ends
    assert not w.update(2.5, 0.1, 2.0)
