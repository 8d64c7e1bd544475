import numpy as np
import pytest

from tautwire.errors import InputFileError, InvalidArgumentError
from tautwire.estimation import read_force_log, write_force_log

HEADER = "t,px,py,pz,fx,fy,fz\n"
ROW0 = "0.0,0.1,0.0,0.2,-1.0,0.0,0.0\n"
ROW1 = "0.004,0.1,0.01,0.2,-1.0,-0.1,0.0\n"


def test_round_trip_with_optional_columns(tmp_path):
    rng = np.random.default_rng(0)
    n = 7
    t = np.cumsum(rng.uniform(0.001, 0.01, n))
    p = rng.normal(size=(n, 3))
    f = rng.normal(size=(n, 3))
    q = rng.normal(size=(n, 4))
    tau = rng.normal(size=(n, 3))
    path = tmp_path / "log.csv"
    write_force_log(path, t, p, f, q, tau)
    log = read_force_log(path)
    assert len(log) == n
    np.testing.assert_array_equal(log.t, t)
    np.testing.assert_array_equal(log.p_gripper, p)
    np.testing.assert_array_equal(log.f_sens, f)
    np.testing.assert_array_equal(log.q_gripper, q)
    np.testing.assert_array_equal(log.torque, tau)
    assert log.lines == tuple(range(2, n + 2))


def test_any_column_order_and_blank_lines(tmp_path):
    path = tmp_path / "log.csv"
    path.write_text("fz,fy,fx,pz,py,px,t\n\n0,0,-1,0.2,0,0.1,0\n0,-0.1,-1,0.2,0.01,0.1,0.004\n\n")
    log = read_force_log(path)
    np.testing.assert_array_equal(log.t, [0.0, 0.004])
    np.testing.assert_array_equal(log.p_gripper[1], [0.1, 0.01, 0.2])
    np.testing.assert_array_equal(log.f_sens[1], [-1.0, -0.1, 0.0])
    assert log.q_gripper is None and log.torque is None
    assert log.lines == (3, 4)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("", r"line 1: empty file"),
        ("t,px,py,pz,fx,fy\n" + ROW0, r"line 1: missing column 'fz'"),
        ("t,px,py,pz,fx,fy,fz,qw\n", r"line 1: missing column 'qx'"),
        ("t,px,py,pz,fx,fy,fz,gx\n", r"line 1, column 8: unknown column 'gx'"),
        ("t,px,py,pz,fx,fy,fz,t\n", r"line 1, column 8: duplicate column 't'"),
        (HEADER + ROW0 + "0.004,0.1,abc,0.2,-1,0,0\n", r"line 3, column 'py': expected a number"),
        (HEADER + ROW0 + "0.004,0.1,0,0.2,nan,0,0\n", r"line 3, column 'fx': expected a finite"),
        (HEADER + ROW0 + "0.004,0.1,0,0.2,inf,0,0\n", r"line 3, column 'fx': expected a finite"),
        (HEADER + ROW0 + "0.004,0.1,0,0.2\n", r"line 3: expected 7 fields"),
        (HEADER + ROW0, r"line 2: too few data rows \(1\), need at least 2"),
        (HEADER, r"line 1: too few data rows \(0\), need at least 2"),
        (HEADER + ROW0 + "0.004,0.1,0,0.2,0,0,0\n", r"line 3, columns 'fx','fy','fz': zero"),
        (HEADER + ROW1 + ROW0, r"line 3, column 't': time must increase"),
        (HEADER + ROW0 + ROW0, r"line 3, column 't': time must increase"),
    ],
)
def test_bad_files_raise_one_line_naming_file_line_and_column(tmp_path, text, expected):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(InputFileError, match=expected) as info:
        read_force_log(path)
    message = str(info.value)
    assert message.startswith(str(path)) and "\n" not in message


def test_missing_file(tmp_path):
    with pytest.raises(InputFileError, match="file not found"):
        read_force_log(tmp_path / "nope.csv")


def test_writer_checks_shapes(tmp_path):
    with pytest.raises(InvalidArgumentError):
        write_force_log(tmp_path / "x.csv", [0.0, 1.0], np.zeros((2, 3)), np.zeros((3, 3)))
