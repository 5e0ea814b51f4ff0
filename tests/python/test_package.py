"""The package as a notebook meets it (issue 38): its version, strict and friendly arguments, and
warnings through Python's warnings. Run by pytest (CTest python.pytest) against the module built
here; tests/python/test_module.py holds it to the programs, bit for bit."""
import re
import warnings

import numpy as np
import pytest

import trebuchet

CA = dict(L1="4.13m", L2="0.88m", L3="0.5m", L4="3.55m", M="3.11t", m="50kg", mb="174kg")
# pytrebuchet's default whipper: its sling goes slack and its weight passes below its frame's
# base before the release (docs/machines.md), two warnings.
WHIPPER = dict(L1="4m", L2="2m", L3="4m", L4="4m", M="100kg", m="3kg", mb="10kg", machine="whipper", H="5m")


def test_version_is_the_projects_in_pep_440_and_the_commit_apart():
    assert trebuchet.__version__ == "0.1.0"
    assert re.fullmatch(r"\d+\.\d+\.\d+", trebuchet.__version__)
    assert trebuchet.__commit__ and trebuchet.__commit__ != trebuchet.__version__


def test_numpy_scalars_give_the_same_record_as_floats():
    # Every loop over an array hands NumPy scalars; they are the same numbers (3110 and 50 exactly).
    plain = trebuchet.shot(dict(CA, M=3110.0, m=50.0, L4=3.55))
    numpy = trebuchet.shot(dict(CA, M=np.int64(3110), m=np.float32(50), L4=np.float64(3.55)))
    assert numpy == plain


def test_a_misspelt_key_names_the_nearest():
    with pytest.raises(trebuchet.TrebuchetError, match='unknown key "theta_i"; did you mean "theta_i_deg"'):
        trebuchet.shot(dict(CA, theta_i=45))
    with pytest.raises(trebuchet.TrebuchetError, match='unknown key "relase"; did you mean "release"'):
        trebuchet.shot(CA, relase="eps")


def test_a_setting_has_one_name_and_its_alias():
    # Issue 51: the flag's word is the keyword; the request's older word is an alias of its row.
    assert trebuchet.shot(CA, quality="range") == trebuchet.shot(CA, release="range")
    claimed = dict(CA, R="150m", T="40kJ")
    assert trebuchet.shot(claimed, tol=1e-9) == trebuchet.shot(claimed, tolerance=1e-9)
    with pytest.raises(trebuchet.TrebuchetError, match='unknown key "tolerence"; did you mean "tolerance"'):
        trebuchet.shot(CA, tolerence=1e-9)
    with pytest.raises(trebuchet.TrebuchetError, match="given already"):
        trebuchet.shot(CA, quality="range", release="Q")
    assert {"quality", "tol", "air", "samples"} <= {row["key"] for row in trebuchet.settings()}


def test_a_wrong_type_is_a_type_error_naming_its_key():
    with pytest.raises(TypeError, match=r"design\.L1: a ndarray is not a value"):
        trebuchet.shot(dict(CA, L1=np.array([4.13, 5.0])))
    with pytest.raises(TypeError, match=r"design\.M: a object is not a value"):
        trebuchet.shot(dict(CA, M=object()))


def test_warnings_come_through_warnings_and_stay_in_the_record():
    with pytest.warns(trebuchet.TrebuchetWarning) as caught:
        answer = trebuchet.shot(WHIPPER)
    texts = [str(w.message) for w in caught]
    # The slack sling and the counterweight below the base (the model's), and the counterweight
    # that reaches 1 m below the ground hanging straight down (H - L2 - L3 = 5 - 6 m: not buildable).
    assert texts == answer["warnings"] and len(texts) == 3
    assert answer["clearance"]["buildable"] is False
    assert "the sling goes slack" in texts[0]


def test_a_test_can_turn_the_warnings_into_errors():
    with warnings.catch_warnings():
        warnings.simplefilter("error", trebuchet.TrebuchetWarning)
        with pytest.raises(trebuchet.TrebuchetWarning, match="the sling goes slack"):
            trebuchet.shot(WHIPPER)


def test_an_engine_without_warnings_warns_nothing():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert trebuchet.shot(CA)["warnings"] == []


def test_a_monte_carlo_stops_on_sigint_with_no_thread_left():
    # In a process of its own, so that the signal is its own (tests/python/interrupt.py).
    import subprocess
    import sys
    from pathlib import Path

    done = subprocess.run([sys.executable, str(Path(__file__).with_name("interrupt.py"))], capture_output=True, text=True, timeout=120)
    print(done.stdout, done.stderr)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "KeyboardInterrupt" in done.stdout


def test_monte_carlo_threads_give_the_same_answer():
    design = dict(CA, M="2.9t..3.3t")
    one = trebuchet.monte_carlo(design, samples=200, threads=1)
    two = trebuchet.monte_carlo(design, samples=200, threads=2)
    assert np.array_equal(one["samples_R"], two["samples_R"], equal_nan=True)
    assert one["percentiles"] == two["percentiles"]
    with pytest.raises(TypeError, match="threads"):
        trebuchet.monte_carlo(design, samples=10, threads=0)


def test_to_frame_gives_pandas_a_row_a_sample_a_moment_or_a_record():
    pd = pytest.importorskip("pandas")
    run = trebuchet.monte_carlo(dict(CA, M="2.9t..3.3t"), samples=50, threads=1)
    samples = trebuchet.to_frame(run)
    assert isinstance(samples, pd.DataFrame) and len(samples) == 50
    assert np.array_equal(samples["R"].to_numpy(), run["samples_R"], equal_nan=True) and "M" in samples
    moments = trebuchet.to_frame(trebuchet.shot(CA, series=True))
    assert len(moments) > 10 and "t" in moments
    records = trebuchet.to_frame([trebuchet.shot(CA), trebuchet.shot(dict(CA, m="60kg"))])
    # A heavier stone, the same engine: it flies less far.
    assert len(records) == 2 and records["R"].iloc[0] > records["R"].iloc[1]


def test_a_sweep_is_its_points_shot_alone_and_frames_a_row_a_point():
    # Each point of a what-if sweep is the shot of its engine alone, every number equal.
    answer = trebuchet.sweep(CA, "L4=2.5m..4.5m", points=5, air=True)
    assert answer["vary"] == "L4" and len(answer["points"]) == 5
    for point in answer["points"]:
        L4 = point["engine"]["L4"]
        assert point == trebuchet.shot(dict(CA, L4=L4), air=True)
    assert answer["points"][0]["engine"]["L4"] == 2.5 and answer["points"][-1]["engine"]["L4"] == 4.5
    frame = trebuchet.to_frame(answer)
    assert list(frame["L4"]) == answer["values"] == [p["engine"]["L4"] for p in answer["points"]]
    assert list(frame["R"]) == [p["R"] for p in answer["points"]]
    with pytest.raises(trebuchet.TrebuchetError, match="no value of an engine to vary"):
        trebuchet.sweep(CA, "R=1m..2m")


def test_a_projectile_material_by_name_is_its_density():
    # iron is 7870 kg/m3: the same shot as the density given as a number.
    by_name = trebuchet.shot(CA, air={"projectile_density": "iron"})
    assert by_name == trebuchet.shot(CA, air={"projectile_density": 7870})
    assert by_name["R"] > trebuchet.shot(CA, air=True)["R"]  # a denser ball is smaller for its mass: less drag, farther


def test_the_module_agrees_with_the_programs():
    # tests/python/test_module.py holds every function to trebuchet-calc and trebuchet-verify, bit
    # for bit; the programs come from CTest (TREBUCHET_CALC, TREBUCHET_VERIFY).
    import os
    import subprocess
    import sys
    from pathlib import Path

    calc, verify = os.environ.get("TREBUCHET_CALC"), os.environ.get("TREBUCHET_VERIFY")
    if not (calc and verify):
        pytest.skip("give the programs' paths in TREBUCHET_CALC and TREBUCHET_VERIFY")
    done = subprocess.run([sys.executable, str(Path(__file__).with_name("test_module.py")), calc, verify], capture_output=True, text=True, timeout=600)
    print(done.stdout)
    assert done.returncode == 0, done.stdout + done.stderr
