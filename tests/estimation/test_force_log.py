import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

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
    assert log.lines.tolist() == list(range(2, n + 2))


def test_any_column_order_and_blank_lines(tmp_path):
    path = tmp_path / "log.csv"
    path.write_text("fz,fy,fx,pz,py,px,t\n\n0,0,-1,0.2,0,0.1,0\n0,-0.1,-1,0.2,0.01,0.1,0.004\n\n")
    log = read_force_log(path)
    np.testing.assert_array_equal(log.t, [0.0, 0.004])
    np.testing.assert_array_equal(log.p_gripper[1], [0.1, 0.01, 0.2])
    np.testing.assert_array_equal(log.f_sens[1], [-1.0, -0.1, 0.0])
    assert log.q_gripper is None and log.torque is None
    assert log.lines.tolist() == [3, 4]


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


def test_a_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "bom.csv"
    path.write_bytes(b"\xef\xbb\xbf" + (HEADER + ROW0 + ROW1).encode())
    np.testing.assert_array_equal(read_force_log(path).t, [0.0, 0.004])


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        ("1_0", "expected a number such as 0.25"),
        ("0x10", "expected a number such as 0.25"),
        ("1e999", "expected a finite number"),
        ("-Infinity", "expected a finite number"),
        ("", "expected a number such as 0.25"),
    ],
)
def test_what_python_float_reads_but_a_log_must_not_hold(tmp_path, value, expected):
    path = tmp_path / "bad.csv"
    path.write_text(HEADER + ROW0 + f"0.004,0.1,0,{value},-1,0,0\n")
    with pytest.raises(InputFileError, match=f"line 3, column 'pz': {expected}"):
        read_force_log(path)


def test_quoted_fields_and_crlf_read_as_plain_ones(tmp_path):
    plain, quoted = tmp_path / "plain.csv", tmp_path / "quoted.csv"
    plain.write_text(HEADER + ROW0 + ROW1)
    rows = [",".join(f'"{v}"' for v in r.strip().split(",")) for r in (ROW0, ROW1)]
    quoted.write_bytes(("\r\n".join([HEADER.strip(), *rows]) + "\r\n").encode())
    a, b = read_force_log(plain), read_force_log(quoted)
    np.testing.assert_array_equal(a.f_sens, b.f_sens)
    assert b.lines.tolist() == [2, 3]


def test_the_first_bad_line_is_named_across_blocks(tmp_path, monkeypatch):
    from tautwire.estimation import force_log

    monkeypatch.setattr(force_log, "CHUNK_LINES", 4)
    n = 15
    t = np.arange(n) * 0.004
    p = np.tile([0.1, 0.0, 0.2], (n, 1))
    f = np.tile([-1.0, 0.0, 0.0], (n, 1))
    path = tmp_path / "log.csv"
    write_force_log(path, t, p, f)
    good = read_force_log(path)
    assert good.lines.tolist() == list(range(2, n + 2))
    lines = path.read_text().split("\n")
    lines[9] = lines[9].replace("-1.0", "-1_0")  # line 10 of the file
    lines[13] = lines[13].replace("-1.0", "oops")
    path.write_text("\n\n".join(lines))  # blank lines between: line 10 is now 19
    with pytest.raises(InputFileError, match=r"line 19, column 'fx': expected a number"):
        read_force_log(path)


@settings(max_examples=25, deadline=None)
@given(
    st.lists(
        st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).filter(lambda x: abs(x) > 1e-3),
        min_size=14,
        max_size=14,
    )
)
def test_numpy_and_field_by_field_parsing_agree(tmp_path_factory, values):
    from tautwire.estimation import force_log

    path = tmp_path_factory.mktemp("log") / "log.csv"
    v = np.array(values).reshape(2, 7)
    v[:, 0] = [0.0, 1.0]
    write_force_log(path, v[:, 0], v[:, 1:4], v[:, 4:7])
    lines = path.read_text().split("\n")
    fast = force_log._fast_table(lines[1:], 1, 7)
    slow = force_log._slow_table("x", lines[1:], 1, [(c, i) for i, c in enumerate("abcdefg")], 7)
    assert fast is not None
    np.testing.assert_array_equal(fast[0], slow[0])
    np.testing.assert_array_equal(fast[1], slow[1])
