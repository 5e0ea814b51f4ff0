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
    with pytest.raises(trebuchet.TrebuchetError, match='unknown key "tolerence"; did you mean "tolerance"') as refused:
        trebuchet.shot(CA, tolerence=1e-9)
    assert refused.value.names == ["tolerence"]  # the key as given (issue 62)
    with pytest.raises(trebuchet.TrebuchetError, match="both give"):
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
    # More threads than the programs take is refused as they refuse it (issue 62).
    with pytest.raises(trebuchet.TrebuchetError, match="at most 65536") as refused:
        trebuchet.monte_carlo(design, samples=10, threads=10**30)
    assert refused.value.names == ["threads"]


def test_a_monte_carlo_report_given_back_is_the_same_run():
    # Its "design" holds the ranges and spreads as text, the spread wind in its air, the target
    # level, the samples, seed and claim: given back, the same draws come again, bit for bit.
    run = trebuchet.monte_carlo(dict(CA, M="2.9t..3.3t", L4="3.55m±0.1m"), air={"wind": "0m/s..4m/s"}, target_level="-5m", samples=60,
                                seed=11, claim="280m", threads=2)
    assert run["design"]["M"] == "2900kg..3300kg" and run["design"]["air"]["wind"] == "0m/s..4m/s" and run["design"]["seed"] == 11
    again = trebuchet.monte_carlo(run, threads=1)
    assert again["samples"] == 60 and again["percentiles"] == run["percentiles"] and again["claim"] == run["claim"]
    assert np.array_equal(again["samples_R"], run["samples_R"], equal_nan=True)
    # A keyword over the report's own changes that one thing: a fixed wind is no longer drawn.
    calm = trebuchet.monte_carlo(run, air={"wind": "0m/s"}, samples=20)
    assert [u["option"] for u in calm["uncertain"]] == ["L4", "M"] and calm["design"]["air"]["wind"] == 0
    # complete's report, with its spread wind, is given back as attested; each report under its own key.
    completed = trebuchet.monte_carlo(attested=dict(Lb="9.5m", M="2.5t..3.5t", m="50kg", air={"wind": "0..4m/s"}), samples=4, threads=1)
    assert trebuchet.monte_carlo(attested=completed, threads=1)["percentiles"] == completed["percentiles"]
    with pytest.raises(trebuchet.TrebuchetError, match="give it as design"):
        trebuchet.monte_carlo(attested=run)
    with pytest.raises(trebuchet.TrebuchetError, match="attested=report"):
        trebuchet.monte_carlo(completed)


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


# Issue 50: records that read back, and a notebook's friction.

def test_a_record_is_shot_again_as_the_same_shot_with_its_settings():
    first = trebuchet.shot(dict(CA, pin_angle_deg=40), air=True, wind="3m/s", target_level="-2m")
    assert trebuchet.shot(first) == first  # every number, bit for bit, and the settings it carries
    # A keyword replaces the record's own setting: vacuum flies farther than air.
    assert trebuchet.shot(first, air=False)["assumptions"]["air"] == "vacuum"
    assert trebuchet.shot(first, air=False)["R"] > first["R"]
    optimum = trebuchet.optimize("300m", "50kJ")[0]
    assert trebuchet.shot(optimum)["R"] == optimum["R"]


def test_a_failed_sweep_point_keeps_its_row_with_its_error_and_warnings_have_a_column():
    pytest.importorskip("pandas")
    for vary in ["L4=0m..5m", "pin_angle=-180..0", "release_time=0.01s..1s", "release_angle=-90..89"]:
        answer = trebuchet.sweep(CA, vary, points=3)
        frame = trebuchet.to_frame(answer)
        assert len(frame) == 3 and list(frame[frame.columns[0]]) == answer["values"]
        failed = [i for i, p in enumerate(answer["points"]) if "error" in p]
        assert failed, vary  # each range starts where no shot is made
        for i in failed:
            assert frame["error"].iloc[i] == answer["points"][i]["error"] and np.isnan(frame["R"].iloc[i])
    frame = trebuchet.to_frame([trebuchet.shot(WHIPPER, release_angle_deg=45)])
    assert "slack" in frame["warnings"].iloc[0] and frame["error"].iloc[0] == ""


def test_compare_and_contest_are_the_programs():
    machines = trebuchet.compare(CA)
    assert [r.get("machine") or r["engine"].get("machine", "hinged") for r in machines] == ["hinged", "fixed", "floating-arm", "whipper"]
    best = trebuchet.contest("0.5kg", D="5cm", max_width="3m", max_height="3m", max_M="300kg")
    assert best["limits"]["max_width"]["measured"] <= 3 * (1 + 1e-9)
    every = trebuchet.contest("0.5kg", machine="all", D="5cm", max_width="3m", max_height="3m", max_M="300kg")
    assert set(every) == {"hinged", "fixed", "floating-arm"} and every["hinged"]["R"] == best["R"]


def test_the_release_and_the_machine_may_be_keywords_and_help_names_them():
    assert trebuchet.shot(CA, pin_angle_deg=35) == trebuchet.shot(dict(CA, pin_angle_deg=35))
    assert trebuchet.shot(CA, machine="fixed")["engine"]["machine"] == "fixed"
    for word in ["release_time", "release_angle_deg", "pin_angle_deg", "machine"]:
        assert word in trebuchet.shot.__doc__


def test_keywords_beside_a_record_go_to_its_engine():
    record = trebuchet.shot(CA, air=True, wind="3m/s")
    # A release, the machine and fit's capacity replace the record's own, as they do beside a design.
    assert trebuchet.shot(record, pin_angle_deg=35)["R"] == trebuchet.shot(dict(CA, pin_angle_deg=35), air=True, wind="3m/s")["R"]
    assert trebuchet.shot(record, machine="fixed")["engine"]["machine"] == "fixed"
    fitted = trebuchet.fit(record, "300m", "20kJ")
    # fit sizes the engine in vacuum (the paper's capacity); it solves to about 1e-10 (read_back.py), 1e-6 is far above that
    assert fitted["predicted"]["R"] == 300 and fitted["R_vacuum"] == pytest.approx(300, rel=1e-6)
    completion = trebuchet.complete(dict(Lb="9.5m", M="3t", m="50kg"))
    assert trebuchet.fit(completion, "200m", "20kJ")["predicted"]["R"] == 200
    # A release over a record's own release replaces it, of any form, as the programs' flag does.
    pinned = trebuchet.shot(record, pin_angle_deg=35)
    assert trebuchet.shot(pinned, release_angle_deg=40)["engine"].get("pin_angle_deg") is None
    # One detail of the air replaces the record's, the others kept.
    calm = trebuchet.shot(record, wind=0)["assumptions"]["air"]
    assert calm == dict(record["assumptions"]["air"], wind=0.0)


def test_refusals_name_their_key():
    with pytest.raises(trebuchet.TrebuchetError) as refused:
        trebuchet.shot(dict(CA, M=-3))
    assert refused.value.names == ["M"]
    for bad in [float("nan"), float("inf"), np.float64("-inf")]:
        with pytest.raises(trebuchet.TrebuchetError, match="design.L4: .* is not a finite number") as refused:
            trebuchet.shot(dict(CA, L4=bad))
        assert refused.value.names == ["L4"]
    circular = dict(CA)
    circular["site"] = circular
    deep = {}
    for _ in range(5000):
        deep = {"a": deep}
    for design in [circular, dict(CA, site=deep)]:
        with pytest.raises(trebuchet.TrebuchetError, match="nests lists or dicts") as refused:
            trebuchet.shot(design)
        assert refused.value.kind == "usage"
    for key in [float("nan"), (1, 2)]:
        with pytest.raises(TypeError, match="give each key as a text"):
            trebuchet.shot({**CA, key: 1})
    # Bad input is the same for every machine: raised once, not returned three times.
    with pytest.raises(trebuchet.TrebuchetError) as refused:
        trebuchet.contest("-1kg", machine="all", D="5cm")
    assert refused.value.names == ["m"]


def test_monte_carlo_and_fields_follow_the_programs_rules():
    with pytest.raises(trebuchet.TrebuchetError, match="range .* or a spread"):
        trebuchet.monte_carlo(CA, samples=10)
    with pytest.raises(trebuchet.TrebuchetError, match="range .* or a spread"):
        trebuchet.monte_carlo(CA, samples=10, claim="100m")
    with pytest.raises(trebuchet.TrebuchetError, match="splits the run") as refused:
        trebuchet.monte_carlo(dict(CA, M="3t..3.2t"), first=0, count=5)
    assert refused.value.names == ["count", "first"]
    assert "machine" in [f["key"] for f in trebuchet.fields()]


def test_the_stubs_keywords_are_those_the_library_takes():
    # Each keyword the type hints name is one the request takes (a setting, a material row, the
    # release, the machine) or the wrapper's own: so a type checker that refuses relase= refuses
    # nothing the library takes by mistake.
    import ast
    import pathlib
    stub = ast.parse(pathlib.Path(trebuchet.__file__).with_suffix(".pyi").read_text())
    settings = trebuchet.settings()
    fields = trebuchet.fields()
    own = {"series", "threads", "progress", "points", "R", "T", "m", "attested", "design"}
    requests = {"shot": "shot", "fit": "shot", "sweep": "sweep", "compare": "compare", "contest": "contest", "complete": "complete",
                "monte_carlo": "monte_carlo", "optimize": "optimize"}
    for node in stub.body:
        if isinstance(node, ast.FunctionDef) and node.name in requests:
            assert node.args.kwarg is None, f"{node.name} takes **settings: its keywords are unchecked"
            request = requests[node.name]
            taken = {name for s in settings if request in s["requests"] for name in [s["key"], *s["aliases"]]}
            taken |= {name for f in fields if f["group"] in ("material", "release") or f["key"] == "machine" for name in [f["key"], *f["aliases"]]}
            taken |= {"theta_i_deg", "theta", "F", "l", "D", "box_width", "box_height", "rope_mass", "pouch_mass", "pin_friction", "projectile_diameter"}
            # Each input of the design (every row of fields() the function's operation takes, with
            # its aliases) is a keyword over the design's own, and the stub names each.
            operations = {"complete": {"complete"}, "monte_carlo": {"shot", "complete"}, "contest": set(), "optimize": set()}.get(node.name, {"shot"})
            inputs = {name for f in fields if set(f["operations"]) & operations and f["group"] not in ("capacity", "material")
                      for name in [f["key"], *f["aliases"]]} - ({"machine"} if node.name == "compare" else set())  # compare chooses the machine
            named = {argument.arg for argument in node.args.kwonlyargs + node.args.args[1:]}
            for name in named:
                assert name in taken | inputs | own, f"{node.name}({name}=...) is no key the library takes"
            assert not inputs - named, f"{node.name} takes {sorted(inputs - named)} as keywords, which its stub does not name"


def test_complete_refuses_a_shots_input_by_name():
    with pytest.raises(trebuchet.TrebuchetError, match="attested.beam_cm: complete does not take") as refused:
        trebuchet.complete(dict(Lb="9.5m", M="3t", m="50kg", beam_cm="2m"))
    assert refused.value.names == ["beam_cm"]


# Issue 62: every value a user gives is used, refused or passed through in plain sight.
E = dict(L1=4.13, L2=0.88, F=2 / 3, L4=3.55, M=3110, m=50, mb=174)


def test_a_number_under_a_key_that_is_no_input_is_refused_by_name():
    # A number (or a quantity) meant for the engine must not pass unread: the refusal names the
    # key and the place for a user's own numbers.
    for key, value in [("counterweight", 3000), ("weight", "0.5kg"), ("year", "1304")]:
        with pytest.raises(trebuchet.TrebuchetError, match=f"design.{key}: .* is a number under a key that is no input") as refused:
            trebuchet.shot(dict(E, **{key: value}))
        assert refused.value.kind == "usage" and refused.value.names == [key]
        assert '"notes"' in str(refused.value)
    # Near an input's name (the peer's slingMass is our pouch_mass): the input is named.
    with pytest.raises(trebuchet.TrebuchetError, match='did you mean "pouch_mass"'):
        trebuchet.shot(dict(E, sling_mass="0.5kg"))


def test_the_peers_sling_mass_is_the_pouchs():
    # Trebuchator's slingMass is a mass at the sling's end, carried with the stone: our pouch_mass.
    assert trebuchet.shot(dict(E, slingMass=0.5))["R"] == trebuchet.shot(dict(E, pouch_mass=0.5))["R"]
    assert trebuchet.shot(dict(E, slingMass=0.5))["R"] != trebuchet.shot(E)["R"]


def test_texts_and_notes_pass_through_with_a_warning_naming_each_key():
    with pytest.warns(trebuchet.TrebuchetWarning, match="site: passed through unread") as caught:
        record = trebuchet.shot(dict(E, site="Alcalá", notes={"year": 1304, "catalogue": "B12"}))
    assert record["passed"] == {"site": "Alcalá", "notes": {"year": 1304, "catalogue": "B12"}}
    assert {str(w.message).split(":")[0] for w in caught} == {"site", "notes"}
    # The record read back keeps them, and its shot is the same.
    with pytest.warns(trebuchet.TrebuchetWarning):
        again = trebuchet.shot(record)
    assert again["passed"] == record["passed"] and again["R"] == record["R"]


def test_a_value_beside_a_records_engine_is_refused_and_a_keyword_goes_over_it():
    record = trebuchet.shot(E)
    with pytest.raises(trebuchet.TrebuchetError, match='"L4" beside a record\'s "engine" is not read') as refused:
        trebuchet.shot(dict(record, L4=2.0))
    assert refused.value.names == ["L4"]
    with pytest.raises(trebuchet.TrebuchetError, match='"tol" beside a record\'s "engine"'):
        trebuchet.shot(dict(record, tol=0.001))
    # The same value as a keyword over the record is the shot of the design with it (56.94 m).
    assert trebuchet.shot(record, L4=2.0)["R"] == trebuchet.shot(dict(E, L4=2.0))["R"]


def test_every_input_is_a_keyword_with_the_result_of_its_key_in_the_design():
    assert trebuchet.shot(E, rope_mass=0.3) == trebuchet.shot(dict(E, rope_mass=0.3))
    assert trebuchet.shot(E, theta=40) == trebuchet.shot(dict(E, theta_i_deg=40))
    # A keyword over the design's own under another name of the same input replaces it.
    assert trebuchet.shot(dict(E, theta=40), theta_i_deg=35) == trebuchet.shot(dict(E, theta_i_deg=35))
    assert trebuchet.compare(E, M=3000) == trebuchet.compare(dict(E, M=3000))
    attested = dict(Lb="5m", M="3t", m="50kg")
    assert trebuchet.complete(attested, L4="3.5m") == trebuchet.complete(dict(attested, L4="3.5m"))
    # complete's own inputs (Lb, l, drop) and a range, completed at its middle, as keywords too.
    assert trebuchet.complete(attested, Lb="9.5m") == trebuchet.complete(dict(attested, Lb="9.5m"))
    assert trebuchet.complete(attested, M="2.5t..3.5t") == trebuchet.complete(dict(attested, M="2.5t..3.5t"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a keyword over a run's value is the caller's own: no note
        trebuchet.monte_carlo(attested=dict(attested, M="2.5t..3.5t"), Lb="6m", samples=2)
    run = trebuchet.monte_carlo(E, M="2.9t..3.3t", samples=20)
    assert run["percentiles"] == trebuchet.monte_carlo(dict(E, M="2.9t..3.3t"), samples=20)["percentiles"]


def test_a_monte_carlo_run_leaves_out_a_calculators_capacity_with_a_warning():
    # One rule with the programs: a design's R and T (a calculator's record) are not checked by a
    # run, which reports their spread; a tolerance without them is refused by name.
    ca = trebuchet.design(R="150m", m="50kg")
    with pytest.warns(trebuchet.TrebuchetWarning, match=r"design.R, design.T: the capacity the design gives is not checked"):
        run = trebuchet.monte_carlo(dict(ca, M="2.9t..3.3t"), samples=20)
    assert run["worked"] == 20
    with pytest.raises(trebuchet.TrebuchetError, match="design.tol: a Monte Carlo run checks no capacity") as refused:
        trebuchet.monte_carlo(dict(E, M="2.9t..3.3t", tol="abc"), samples=20)
    assert refused.value.names == ["tol"]


def test_a_capacity_outside_the_table_names_the_givens():
    # The keys the user gave come first; extrapolate, the way out, after them.
    with pytest.raises(trebuchet.TrebuchetError, match="change R to lie there, or change m") as refused:
        trebuchet.design(R="5000m", m="50kg")
    assert refused.value.names == ["R", "m", "extrapolate"]


def test_every_record_frames_with_its_machine_and_its_engines_inputs():
    pytest.importorskip("pandas")
    # compare: each row names its machine, from its engine or (a refused machine) its own key.
    machines = trebuchet.compare(CA)
    frame = trebuchet.to_frame(machines)
    assert list(frame["machine"]) == ["hinged", "fixed", "floating-arm", "whipper"]
    # A list of shots carries each engine's inputs beside its figures.
    shots = trebuchet.to_frame([trebuchet.shot(CA), trebuchet.shot(dict(CA, M="3t"))])
    assert list(shots["M"]) == [3110, 3000] and list(shots["L4"]) == [3.55, 3.55] and list(shots["m"]) == [50, 50]
    # One record is one row; contest's machines a row each, a refused one with its error.
    one = trebuchet.to_frame(trebuchet.shot(CA))
    assert len(one) == 1 and one["R"].iloc[0] == trebuchet.shot(CA)["R"] and one["machine"].iloc[0] == "hinged"
    best = {"hinged": trebuchet.shot(CA), "fixed": trebuchet.TrebuchetError("refused", "usage", [])}
    frame = trebuchet.to_frame(best)
    assert list(frame["machine"]) == ["hinged", "fixed"] and list(frame["error"]) == ["", "refused"]


def test_every_key_of_every_record_is_read_or_refused_at_this_door():
    # Each record kind the library writes reads back with no key passed through unread (every key
    # is read, or known as the record's own output), and each input of its engine, put beside the
    # engine with another value, is refused by name rather than dropped.
    inputs = {name for f in trebuchet.fields() for name in [f["key"], *f["aliases"]]}
    records = {
        "shot": trebuchet.shot(CA, air=True, wind="2m/s"),
        "fit": trebuchet.fit(CA, "150m", "40kJ"),
        "optimize": trebuchet.optimize("300m", "50kJ")[0],
        "complete": trebuchet.complete(dict(Lb="5m", M="3t", m="50kg")),
        "sweep point": trebuchet.sweep(CA, "L4=3m..4m", points=2)["points"][1],
        "compare": trebuchet.compare(CA)[1],
    }
    for kind, record in records.items():
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            again = trebuchet.shot(record)
        assert "passed" not in again and not [w for w in caught if "passed through" in str(w.message)], kind
        assert again["R"] == record["R"], kind
        for key, value in (record.get("engine") or {}).items():
            if key in inputs and isinstance(value, (int, float)) and not isinstance(value, bool) and value != 0:
                with pytest.raises(trebuchet.TrebuchetError) as refused:
                    trebuchet.shot(dict(record, **{key: value * 1.5}))
                assert refused.value.names == [key], (kind, key)


def test_a_value_beside_a_records_engine_under_another_key_passes_by_name():
    record = trebuchet.shot(E)
    # Beside a record's engine, a key that is no input is passed through by name, never dropped.
    with pytest.warns(trebuchet.TrebuchetWarning, match="year: passed through unread"):
        again = trebuchet.shot(dict(record, year=1304))
    assert again["passed"] == {"year": 1304} and again["R"] == record["R"]
    # A misspelt input beside it is refused with the input meant.
    with pytest.raises(trebuchet.TrebuchetError, match='did you mean "pouch_mass"'):
        trebuchet.shot(dict(record, pouch_mas=0.5))


def test_compare_chooses_the_machine():
    with pytest.raises(trebuchet.TrebuchetError, match="compare builds the engine as each machine") as refused:
        trebuchet.compare(E, machine="fixed")
    assert refused.value.names == ["machine"]


def test_sweep_and_compare_name_what_passes_through():
    with pytest.warns(trebuchet.TrebuchetWarning, match="site: passed through unread"):
        swept = trebuchet.sweep(dict(E, site="Alcalá"), "L4=3m..4m", points=2)
    assert swept["passed"] == {"site": "Alcalá"}
    with pytest.warns(trebuchet.TrebuchetWarning, match="site: passed through unread"):
        machines = trebuchet.compare(dict(E, site="Alcalá"))
    assert all(m["passed"] == {"site": "Alcalá"} for m in machines)
