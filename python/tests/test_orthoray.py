"""The orthoray Python module against the command line (the same answers
on the curated instances), exact numbers both ways, bad input carrying its
file, line and column, certificates that verify and fail when tampered,
and Ctrl-C stopping a run as a limit."""
import json
import os
import signal
import subprocess
import threading
from fractions import Fraction
from pathlib import Path

import pytest

import orthoray

SOURCE = Path(os.environ.get("ORTHORAY_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("ORTHORAY_CLI", "orthoray")
INSTANCES = sorted((SOURCE / "instances").glob("*/*.scene"))


def cli_json(*args):
    done = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True)
    return json.loads(done.stdout)


# Fields that measure time or setup rather than the answer.
TIMING = {"seconds", "setup_seconds", "induction_seconds"}


@pytest.mark.parametrize("path", INSTANCES, ids=lambda p: p.name)
def test_same_answer_as_the_command_line(path):
    ours = orthoray.solve(orthoray.Scene.load(str(path))).as_dict()
    theirs = cli_json("solve", str(path))
    for key in TIMING:
        ours.pop(key, None)
        theirs.pop(key, None)
    assert ours == theirs


def test_instances_are_there():
    assert len(INSTANCES) >= 20


def test_a_scene_built_in_code_with_exact_numbers():
    scene = orthoray.Scene(2)
    for wall in (("x", 0), ("x", 3)):
        scene.add("mirror", wall[0], wall[1], [(0, 5)])
    for wall in (("y", 0), ("y", 5)):
        scene.add("mirror", wall[0], wall[1], [("0", Fraction(3))])
    scene.add_ray((0, 0), (1, 1))
    scene.add_target((3, 5))
    answer = orthoray.solve(scene)
    assert (answer.answer, answer.reason, answer.reflections) == ("yes", "hit", 6)
    assert answer.period is None
    assert scene.elements[1] == {"kind": "mirror", "axis": "x", "side": "", "offset": 3,
                                 "extent": {"y": (0, 5)}}
    assert "mirror x 3 y 0 5" in scene.text()


def test_huge_counts_are_exact_ints():
    side = 10**40 + 1
    scene = orthoray.generate_box([side, 10**40 + 3])
    answer = orthoray.solve(scene, engine="induction")
    assert answer.decided
    assert isinstance(answer.reflections, int)
    assert answer.reflections > 10**39


def test_fractions_come_back_as_fractions():
    scene = orthoray.Scene.parse("dim 2\nmirror x 7/2 y 0 1/3\nray 0 0 1 0\ntarget 1/3 0\n")
    assert scene.elements[0]["offset"] == Fraction(7, 2)
    assert scene.targets == [(Fraction(1, 3), 0)]


def test_floats_are_refused():
    scene = orthoray.Scene(2)
    with pytest.raises(TypeError, match="inexact"):
        scene.add_target((0.5, 1))
    with pytest.raises(TypeError, match="found a bool"):
        scene.add_target((True, 1))


def test_bad_input_carries_file_line_and_column(tmp_path):
    bad = tmp_path / "bad.scene"
    bad.write_text("dim 2\nmirror q 3 y 0 5\nray 0 0 1 0\ntarget 1 0\n")
    with pytest.raises(orthoray.InputError) as caught:
        orthoray.Scene.load(str(bad))
    error = caught.value
    assert (error.file, error.line, error.column) == (str(bad), 2, 8)
    assert str(error).startswith(f"{bad}:2:8: found 'q'")
    assert isinstance(error, ValueError)
    # The command line says the same.
    done = subprocess.run([CLI, "solve", str(bad)], capture_output=True, text=True)
    assert done.returncode == 2 and done.stderr.strip() == str(error)


def test_certificates_verify_and_tampered_ones_fail(tmp_path):
    path = SOURCE / "instances" / "2d" / "box-corner-3x5.scene"
    scene = orthoray.Scene.load(str(path))
    cert = tmp_path / "box.cert"
    orthoray.solve(scene, certificate=str(cert))
    assert orthoray.verify(scene, str(cert)) == (True, "valid: hit, 6 reflections")
    text = cert.read_text()
    cert.write_text(text.replace("reflections 6", "reflections 5"))
    valid, message = orthoray.verify(scene, str(cert))
    assert not valid and message


def test_the_intensity_question_with_a_certificate(tmp_path):
    scene = orthoray.Scene.parse(
        "dim 2\n"
        "splitter x 2 y -1 1 reflectance 1/2 transmittance 1/3\n"
        "ray 0 0 1 0 intensity 1000\n"
        "target 3 0\n"
        "target -1 0\n"
    )
    cert = tmp_path / "intensity.cert"
    answer = orthoray.solve(scene, min_intensity=400, certificate=str(cert))
    assert answer.answer == "no"
    assert [t["answer"] for t in answer.targets] == ["no", "yes"]
    assert answer.targets[1]["intensity"] == 500
    assert orthoray.verify(scene, str(cert)) == (
        True,
        "valid: unlit above intensity 400, 1 reflections, 2 states",
    )
    with pytest.raises(ValueError):
        orthoray.solve(scene, min_intensity=Fraction(1, 2))
    with pytest.raises(TypeError):
        orthoray.solve(scene, min_intensity=0.5)


def test_limits_are_answers_not_errors():
    scene = orthoray.generate_box([10**30 + 7, 10**30 + 9])
    answer = orthoray.solve(scene, engine="lattice", max_steps=1000)
    assert (answer.answer, answer.reason, answer.limit) == ("unknown", "limit", "steps")
    assert answer.reflections == 1000


def test_ctrl_c_stops_the_run_and_keeps_the_partial_answer():
    scene = orthoray.generate_box([10**30 + 7, 10**30 + 9])
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt) as caught:
        orthoray.solve(scene, engine="lattice")
    timer.join()
    partial = caught.value.answer
    assert (partial.reason, partial.limit) == ("limit", "interrupt")
    assert partial.reflections > 0


def test_timeout_is_a_time_limit():
    scene = orthoray.generate_box([10**30 + 7, 10**30 + 9])
    answer = orthoray.solve(scene, engine="lattice", timeout=0.2)
    assert (answer.reason, answer.limit) == ("limit", "time")


def test_pictures_for_notebooks():
    scene = orthoray.Scene.load(str(SOURCE / "instances" / "2d" / "box-corner-3x5.scene"))
    svg = scene._repr_svg_()
    assert svg.startswith("<svg") or svg.startswith("<?xml")
    picture = orthoray.solve(scene)._repr_svg_()
    assert "answer yes, reason hit, reflections 6" in picture
    assert picture.count("<") > svg.count("<")  # the path is drawn too
    assert orthoray.render(scene) == picture


def test_bounds_and_generate_match_the_command_line(tmp_path):
    scene = orthoray.generate_random(dim=2, mirrors=30, seed=7)
    path = tmp_path / "r.scene"
    path.write_text(scene.text())
    done = subprocess.run([CLI, "generate", "random", "--mirrors", "30", "--seed", "7",
                           "-o", str(tmp_path / "cli.scene")], capture_output=True, text=True)
    assert done.returncode == 0
    def statements(text):
        return [line for line in text.splitlines() if line and not line.startswith("#")]
    assert statements(scene.text()) == statements((tmp_path / "cli.scene").read_text())
    ours = orthoray.bounds(scene)
    theirs = cli_json("bounds", str(path))
    assert ours["lattice_states"] == int(theirs["lattice_states"])
    assert ours["points"] == int(theirs["points"])


def test_diagonals_from_python():
    scene = orthoray.Scene(2)
    scene.add_diagonal("mirror", (0, 0), (2, 2))
    scene.add_ray((-1, 1), (1, 0))
    scene.add_target((1, 5))
    answer = orthoray.solve(scene, engine="reference")
    assert (answer.answer, answer.reflections) == ("yes", 1)
    assert scene.elements[0]["diagonal"] == "/"
    with pytest.raises(ValueError):
        scene.add_diagonal("mirror", (0, 0), (2, 3))


def test_version_and_build_info():
    info = orthoray.build_info()
    assert info["orthoray"] == orthoray.__version__
    assert set(info) >= {"gmp", "boost", "compiler", "commit"}


def test_ints_beyond_python_decimal_conversion_limit():
    # Python refuses decimal int<->str conversions over 4300 digits; the
    # module converts through hexadecimal, so coordinates of any size pass.
    big = 10**5000 + 1
    scene = orthoray.Scene(2)
    scene.add("mirror", "x", big, [(0, 1)])
    scene.add_ray((0, 0), (1, 0))
    scene.add_target((big, 0))
    assert scene.elements[0]["offset"] == big
    answer = orthoray.solve(scene)
    assert (answer.answer, answer.reflections) == ("yes", 0)
    # And out: m + n - 2 reflections to the far corner of an m x n box with
    # m, n odd and coprime, a count of 4301 digits.
    m = 10**4300 + 1
    answer = orthoray.solve(orthoray.generate_box([m, m + 2]))
    assert (answer.answer, answer.reflections) == ("yes", 2 * m)
    assert answer.as_dict()["reflections"] == 2 * m


def test_a_signal_handlers_own_exception_goes_through():
    # Only Ctrl-C becomes KeyboardInterrupt; a handler of the caller's
    # (a timeout of theirs, sys.exit on SIGTERM) raises its own exception,
    # which carries the partial answer too.
    class Expired(Exception):
        pass

    def expire(*_):
        raise Expired("the caller's own timeout")

    scene = orthoray.generate_box([10**30 + 7, 10**30 + 9])
    previous = signal.signal(signal.SIGALRM, expire)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        with pytest.raises(Expired) as caught:
            orthoray.solve(scene, engine="lattice")
        assert caught.value.answer.limit == "interrupt"
        assert caught.value.answer.reflections > 0
        signal.signal(signal.SIGALRM, lambda *_: exit(7))
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        with pytest.raises(SystemExit) as stopped:
            orthoray.solve(scene, engine="lattice")
        assert stopped.value.code == 7
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def test_certificates_written_at_once_to_one_path_stay_whole(tmp_path):
    # Each writer has a temporary file of its own: the path ends up holding
    # one whole certificate, the last renamed, never a mix of two.
    scenes = [orthoray.generate_box([10**5 + 1, 10**5 + 3]),
              orthoray.generate_box([10**5 + 3, 10**5 + 7])]
    cert = tmp_path / "shared.cert"
    errors = []

    def write(scene):
        try:
            orthoray.solve(scene, engine="lattice", certificate=str(cert))
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)

    threads = [threading.Thread(target=write, args=(s,)) for s in scenes]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert [orthoray.verify(s, str(cert))[0] for s in scenes].count(True) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["shared.cert"]


def test_misspelled_formats_are_refused(tmp_path):
    box = orthoray.generate_box([3, 5])
    with pytest.raises(ValueError, match="certificate_format: found 'json'"):
        orthoray.solve(box, certificate=str(tmp_path / "c"), certificate_format="json")
    with pytest.raises(ValueError, match="format: found 'jason'"):
        orthoray.Scene.load(str(SOURCE / "instances" / "2d" / "box-corner-3x5.scene"),
                            format="jason")
    with pytest.raises(ValueError, match="cannot write certificate"):
        orthoray.solve(box, certificate=str(tmp_path / "missing" / "c"))


def test_malformed_numbers_and_options_are_value_errors():
    class Broken:
        numerator = 1
        denominator = 0
    scene = orthoray.Scene(2)
    with pytest.raises(ValueError, match="zero denominator"):
        scene.add_target((Broken(), 0))
    with pytest.raises(ValueError, match="ray and one target"):
        orthoray.render(scene)
    with pytest.raises(ValueError, match="ray and one target"):
        orthoray.bounds(scene)
    box = orthoray.generate_box([3, 5])
    with pytest.raises(ValueError, match="timeout"):
        orthoray.solve(box, timeout=float("nan"))
    assert "<svg" in scene.svg()  # a scene with no ray still draws
