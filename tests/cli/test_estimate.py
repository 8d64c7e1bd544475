import json

import numpy as np
import pytest

from tautwire.cli.main import main
from tautwire.estimation import write_force_log
from tautwire.experiments.synthetic_circle import circle


@pytest.fixture
def jump_log(tmp_path):
    d = circle(0, n=260, second_contact_at=190)
    path = tmp_path / "log.csv"
    write_force_log(path, np.arange(260) / 250.0, d.p_gripper, d.f_sens)
    return path, d


def test_json_is_one_object_with_the_contract(jump_log, capsys):
    path, d = jump_log
    assert main(["estimate", str(path), "--json"]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    obj = json.loads(out)  # the whole of stdout is one JSON object
    assert set(obj) >= {"contact", "covariance", "history", "changes", "stiffness"}
    assert np.linalg.norm(np.array(obj["contact"]) - d.contact[-1]) < 2e-3
    assert np.array(obj["covariance"]).shape == (3, 3)
    assert len(obj["history"]) == 260
    assert obj["history"][0] == {"t": 0.0, "contact": None, "std": None}
    assert obj["history"][-1]["contact"] == obj["contact"]
    assert obj["history"][100]["t"] == pytest.approx(0.4)
    assert len(obj["history"][100]["std"]) == 3
    assert len(obj["changes"]) == 1 and 190 <= obj["changes"][0] <= 195
    assert obj["stiffness"] is None


def test_options_are_passed_through(jump_log, capsys):
    path, _ = jump_log
    args = ["estimate", str(path), "--json", "--process-noise", "1e-7", "--force-noise", "0.1"]
    assert main([*args, "--mass-per-length", "0.0"]) == 0
    a = json.loads(capsys.readouterr().out)
    assert main(["estimate", str(path), "--json"]) == 0
    b = json.loads(capsys.readouterr().out)
    assert a["history"][100]["std"] != b["history"][100]["std"]


def test_readable_summary(jump_log, capsys):
    path, _ = jump_log
    assert main(["estimate", str(path)]) == 0
    out = capsys.readouterr().out
    assert "contact:" in out and "contact changes at rows: " in out and "stiffness" in out


def test_missing_file_is_one_line_exit_1(tmp_path, capsys):
    assert main(["estimate", str(tmp_path / "none.csv"), "--json"]) == 1
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1 and "none.csv: file not found" in err
    assert "Traceback" not in err


def test_bad_row_is_one_line_exit_1(tmp_path, capsys):
    path = tmp_path / "bad.csv"
    path.write_text("t,px,py,pz,fx,fy,fz\n0,0,0,0,1,0,0\n0.1,0,0,0,x,0,0\n")
    assert main(["estimate", str(path)]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert "line 3, column 'fx': expected a number" in err


def test_bad_option_value_is_one_line(jump_log, capsys):
    path, _ = jump_log
    assert main(["estimate", str(path), "--mass-per-length", "-1"]) == 1
    _, err = capsys.readouterr()
    assert err.count("\n") == 1 and "mass_per_length" in err
