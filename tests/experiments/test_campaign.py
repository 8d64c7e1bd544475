import importlib.util
import sys
import types

import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.experiments.campaign import CampaignError, run_campaign
from tautwire.experiments.trial import TrialResult, TrialSpec, trial_seed

from . import fake_trials

HAS_RAY = importlib.util.find_spec("ray") is not None


def specs(letters: str = "DI", n: int = 6, seed: int = 0) -> list[TrialSpec]:
    return [TrialSpec(c, i, trial_seed(seed, c, i)) for c in letters for i in range(n)]


def keys(results: tuple[TrialResult, ...] | list[TrialResult]) -> list[tuple[str, int]]:
    return [(r.letter, r.index) for r in results]


def test_serial_streams_each_result_and_orders_by_letter_and_index() -> None:
    todo = list(reversed(specs()))
    seen: list[TrialResult] = []
    campaign = run_campaign(todo, fake_trials.quick_trial, backend="serial", on_result=seen.append)
    assert keys(seen) == keys([fake_trials.quick_trial(s) for s in todo])  # completion order
    assert keys(campaign.results) == keys(specs())
    assert campaign.finished == campaign.planned == 12
    assert campaign.failures == 4  # index 2 and 5 of each letter
    assert not campaign.interrupted


def test_local_results_equal_serial_results_whatever_the_completion_order() -> None:
    todo = list(reversed(specs()))
    seen: list[TrialResult] = []
    local = run_campaign(
        todo, fake_trials.quick_trial, backend="local", workers=2, on_result=seen.append
    )
    serial = run_campaign(todo, fake_trials.quick_trial, backend="serial")
    assert sorted(keys(seen)) == keys(specs())  # every result streamed exactly once
    assert local.results == serial.results
    assert local.workers == 2 and local.backend == "local"


def test_a_trial_that_raises_in_a_worker_is_recorded_and_the_rest_finish() -> None:
    campaign = run_campaign(specs("D", 4), fake_trials.raising_trial, workers=2)
    assert keys(campaign.results) == keys(specs("D", 4))
    failed = campaign.results[1]
    assert failed.cause == "error" and not failed.success
    assert "RuntimeError: boom in the trial" in failed.detail
    assert failed.name == "single_arm_tension"  # from the catalogue
    assert [r.outcome for r in campaign.results] == ["success", "failure", "failure", "success"]
    assert campaign.results[2].cause == "timeout"


def test_a_wrong_return_and_a_system_exit_are_errors() -> None:
    wrong = run_campaign(specs("D", 1), fake_trials.wrong_type_trial, backend="serial")
    assert wrong.results[0].cause == "error" and "returned str" in wrong.results[0].detail
    exiting = run_campaign(specs("D", 3), fake_trials.exiting_trial, workers=1)
    assert [r.cause for r in exiting.results] == ["error", None, "timeout"]
    assert "SystemExit" in exiting.results[0].detail


def test_a_worker_that_dies_costs_only_its_trial() -> None:
    todo = specs("DI", 4)
    seen: list[TrialResult] = []
    campaign = run_campaign(todo, fake_trials.dying_trial, workers=2, on_result=seen.append)
    assert keys(campaign.results) == keys(todo)
    assert len(seen) == len(todo)
    by_key = {(r.letter, r.index): r for r in campaign.results}
    assert by_key["D", 1].cause == "crashed" and "exit code 3" in by_key["D", 1].detail
    assert by_key["D", 2].cause == "crashed" and "SIGSEGV" in by_key["D", 2].detail
    others = [r for k, r in by_key.items() if k not in (("D", 1), ("D", 2))]
    assert others == [fake_trials.quick_trial(TrialSpec(r.letter, r.index, r.seed)) for r in others]


def test_a_trial_past_its_timeout_is_stopped_and_the_rest_finish() -> None:
    campaign = run_campaign(specs("D", 4), fake_trials.hanging_trial, workers=2, trial_timeout=2.0)
    assert [r.cause for r in campaign.results] == [None, "hung", "timeout", None]
    assert "no result after 2 s" in campaign.results[1].detail


@pytest.mark.parametrize("backend", ["serial", "local"])
def test_an_interrupt_keeps_the_finished_trials(backend: str) -> None:
    seen: list[TrialResult] = []

    def stop_after_three(result: TrialResult) -> None:
        seen.append(result)
        if len(seen) == 3:
            raise KeyboardInterrupt

    campaign = run_campaign(
        specs(), fake_trials.quick_trial, backend=backend, workers=2, on_result=stop_after_three
    )
    assert campaign.interrupted
    assert campaign.finished == 3 and campaign.planned == 12
    assert sorted(keys(campaign.results)) == sorted(keys(seen))


def test_worker_output_goes_to_one_log_per_worker(tmp_path) -> None:  # type: ignore[no-untyped-def]
    run_campaign(specs("D", 3), fake_trials.printing_trial, workers=2, log_dir=tmp_path)
    text = "".join(p.read_text() for p in sorted(tmp_path.glob("worker-*.log")))
    for i in range(3):
        assert f"=== trial D:{i} seed {trial_seed(0, 'D', i)}" in text
        assert f"warning from D:{i}" in text


def test_bad_arguments_are_refused() -> None:
    with pytest.raises(InvalidArgumentError, match="serial, local, ray"):
        run_campaign(specs(), fake_trials.quick_trial, backend="cluster")
    with pytest.raises(InvalidArgumentError, match="at least 1"):
        run_campaign(specs(), fake_trials.quick_trial, workers=0)
    with pytest.raises(InvalidArgumentError, match="trial_timeout must be positive"):
        run_campaign(specs(), fake_trials.quick_trial, trial_timeout=0.0)
    with pytest.raises(InvalidArgumentError, match="D:0 is listed twice"):
        run_campaign(specs("D", 1) * 2, fake_trials.quick_trial)


def test_a_trial_function_that_workers_cannot_load_is_a_clear_error() -> None:
    with pytest.raises(CampaignError, match="module level"):
        run_campaign(specs("D", 1), lambda s: fake_trials.quick_trial(s), workers=1)
    ghost = types.ModuleType("tautwire_ghost_module")
    exec("def trial(spec):\n    return None\n", ghost.__dict__)
    sys.modules[ghost.__name__] = ghost
    try:
        with pytest.raises(CampaignError, match="could not load the trial function"):
            run_campaign(specs("D", 1), ghost.trial, workers=1)
    finally:
        del sys.modules[ghost.__name__]


def test_the_ray_backend_names_its_extra_when_ray_is_missing(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setitem(sys.modules, "ray", None)  # import ray raises ImportError
    with pytest.raises(CampaignError, match=r"tautwire\[ray\]"):
        run_campaign(specs("D", 1), fake_trials.quick_trial, backend="ray")


@pytest.mark.skipif(not HAS_RAY, reason="Ray is not installed (pip install 'tautwire[ray]')")
def test_ray_backend_on_a_local_instance() -> None:
    import ray

    todo = list(reversed(specs("DI", 4)))
    seen: list[TrialResult] = []
    campaign = run_campaign(
        todo, fake_trials.mixed_trial, backend="ray", workers=2, on_result=seen.append
    )
    assert not ray.is_initialized()  # the instance it started is shut down
    assert campaign.backend == "ray" and campaign.workers == 2
    assert keys(campaign.results) == keys(specs("DI", 4)) and len(seen) == 8
    by_key = {(r.letter, r.index): r for r in campaign.results}
    assert by_key["D", 1].cause == "error" and "boom" in by_key["D", 1].detail
    assert by_key["D", 2].cause == "crashed"
    others = [r for k, r in by_key.items() if k not in (("D", 1), ("D", 2))]
    assert others == [fake_trials.quick_trial(TrialSpec(r.letter, r.index, r.seed)) for r in others]


@pytest.mark.skipif(not HAS_RAY, reason="Ray is not installed (pip install 'tautwire[ray]')")
def test_ray_backend_uses_a_running_instance_and_keeps_finished_trials_on_interrupt() -> None:
    import ray

    seen: list[TrialResult] = []

    def stop_after_two(result: TrialResult) -> None:
        seen.append(result)
        if len(seen) == 2:
            raise KeyboardInterrupt

    ray.init(num_cpus=2, include_dashboard=False)
    try:
        campaign = run_campaign(
            specs("D", 8), fake_trials.slow_trial, backend="ray", on_result=stop_after_two
        )
        assert ray.is_initialized()  # not this campaign's to shut down
    finally:
        ray.shutdown()
    assert campaign.interrupted and campaign.finished == 2 and campaign.planned == 8
    assert sorted(keys(campaign.results)) == sorted(keys(seen))
