"""The Python module against the programs: the same engines give the same JSON, a refusal the
same message. Usage: test_module.py CALC VERIFY (with the module on PYTHONPATH)."""
import json
import math
import os
import random
import subprocess
import sys
import tempfile

import numpy as np

import trebuchet

CALC, VERIFY = sys.argv[1], sys.argv[2]
failures = []


def program(*args, stdin=None):
    done = subprocess.run(list(args), input=stdin, capture_output=True, text=True)
    return done


def compare(name, ours, theirs, tolerance=1e-12):
    """Every number of the programs' record, key by key (nested), to `tolerance` relative."""
    worst = 0.0

    def walk(a, b, path):
        nonlocal worst
        if isinstance(b, dict):
            for key in b:
                if key in ("wall_time_s", "simulations"):
                    continue
                if key not in a:
                    failures.append(f"{name}: {path}{key} missing from the module's answer")
                    continue
                walk(a[key], b[key], f"{path}{key}.")
        elif isinstance(b, list):
            if len(a) != len(b):
                failures.append(f"{name}: {path} has {len(a)} items, the program's {len(b)}")
                return
            for k, (x, y) in enumerate(zip(a, b)):
                walk(x, y, f"{path}{k}.")
        elif isinstance(b, (int, float)) and not isinstance(b, bool):
            difference = abs(a - b) / max(abs(b), 1e-300) if b != 0 else abs(a)
            worst = max(worst, difference)
            if difference > tolerance:
                failures.append(f"{name}: {path} {a} against the program's {b}")
        elif a != b:
            failures.append(f"{name}: {path} {a!r} against the program's {b!r}")

    walk(ours, theirs, "")
    return worst


def shot_by_program(design, *flags):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(design, f)
    try:
        done = program(VERIFY, "shot", f.name, "--format", "json", *flags)
    finally:
        os.unlink(f.name)
    return done


engines = {
    "Alcala la Vieja Ca": {"L1": "4.13m", "L2": "0.88m", "F": "2/3", "L4": "3.55m", "M": "3.11t", "m": "50kg", "mb": "174kg"},
    "Denny's engine (tab:Denny)": json.load(open(os.path.join(os.path.dirname(__file__), "..", "cli", "denny_standard.json"))),
}
random.seed(25)
while len(engines) < 22:  # 20 random designs the calculator covers; a pair it refuses is drawn again
    R, m = random.uniform(80, 500), random.uniform(10, 300)
    try:
        engines[f"random design R = {R:.1f} m, m = {m:.1f} kg"] = trebuchet.design(R=R, m=m)
    except trebuchet.TrebuchetError:
        pass

worst = 0.0
for name, design in engines.items():
    done = shot_by_program(design)
    if done.returncode != 0:
        failures.append(f"{name}: the program refused it: {done.stderr.strip()}")
        continue
    worst = max(worst, compare(name, trebuchet.shot(design), json.loads(done.stdout)))
print(f"shots: {len(engines)} engines, worst relative difference {worst:.3g} (tolerance 1e-12)")

# The calculator: the module's design is the program's.
done = program(CALC, "--R", "150m", "--m", "50kg", "--format", "json")
print(f"calculator: worst {compare('calculator', trebuchet.design(R='150m', m='50kg'), json.loads(done.stdout)):.3g}")

# In air with a target below, released for the range, and a series as arrays.
ca = engines["Alcala la Vieja Ca"]
ours = trebuchet.shot(ca, air={"wind": "5m/s"}, release="range", target_level="-10m", series=True)
done = shot_by_program(ca, "--air", "--wind", "5m/s", "--quality", "range", "--target-level", "-10m")
theirs = json.loads(done.stdout)
print(f"air, range, -10 m: worst {compare('air', {k: v for k, v in ours.items() if k != 'series'}, theirs):.3g}")
frames = ours["series"]["frames"]
if not (isinstance(frames["t"], np.ndarray) and frames["t"].dtype == float and np.all(np.diff(frames["t"]) >= 0)):
    failures.append("series: frames.t is not an increasing float array")

# A release set by its pin angle, as a design key: the program's shot, the same key in its file.
ours = trebuchet.shot(dict(ca, pin_angle_deg=30))
theirs = json.loads(shot_by_program(dict(ca, pin_angle_deg=30)).stdout)
print(f"pin angle 30 deg: worst {compare('pin angle', ours, theirs):.3g}")
if abs(ours["pin_angle_at_release_deg"] - 30) > 1e-9:
    failures.append(f"pin angle: released at {ours['pin_angle_at_release_deg']} deg, not 30")

# The other machines, as a design key: the program's shot, bit for bit, and the machine in the record.
for machine in ("fixed", "floating-arm"):
    ours = trebuchet.shot(dict(ca, machine=machine))
    theirs = json.loads(shot_by_program(dict(ca, machine=machine)).stdout)
    compare(machine, ours, theirs)
    if ours["engine"].get("machine") != machine:
        failures.append(f"{machine}: the record's engine does not name its machine")
# The whipper, on pytrebuchet's default parts and frame.
whip = dict(L1="4m", L2="2m", L3="4m", L4="4m", M="100kg", m="3kg", mb="10kg", machine="whipper", H="5m", projectile_diameter="0.2m")
ours, theirs = trebuchet.shot(whip), json.loads(shot_by_program(whip).stdout)
compare("whipper", ours, theirs)
if not ours["t_counterweight_free"] < ours["t_liftoff"]:
    failures.append("whipper: its counterweight does not leave the arm before the ball")

# A refusal: the same message as the program's, as an exception.
bad = dict(ca, L4="-3m")
done = shot_by_program(bad)
message = done.stderr.strip().split(": ", 1)[1]
try:
    trebuchet.shot(bad)
    failures.append("a negative sling was not refused")
except trebuchet.TrebuchetError as e:
    if str(e) != message:
        failures.append(f"refusal: {str(e)!r} against the program's {message!r}")
    if e.kind != "bad_number":
        failures.append(f"refusal: kind {e.kind}")
try:
    trebuchet.shot(dict(ca, M=math.nan))
    failures.append("NaN was not refused")
except trebuchet.TrebuchetError:
    pass

# A near miss is refused with the name meant, as the program refuses it; a settings keyword no
# request takes is refused; another key of a design passes through, named in the answer.
near = dict(ca, theta_i=45)
done = shot_by_program(near)
for request, expected in [(lambda: trebuchet.shot(near), done.stderr.strip().split(": ", 1)[1]),
                          (lambda: trebuchet.shot(ca, relase="eps"), 'shot: unknown key "relase"; did you mean "release"?')]:
    try:
        request()
        failures.append(f"not refused: {expected}")
    except trebuchet.TrebuchetError as e:
        if str(e) != expected or e.kind != "usage":
            failures.append(f"near miss: {str(e)!r} ({e.kind}) against {expected!r}")
passed = trebuchet.shot(dict(ca, site="Ca")).get("passed")
if passed != {"site": "Ca"}:
    failures.append(f"a site's name did not pass through: {passed}")
if not any(f["key"] == "L4" and f["flag"] == "--L4" for f in trebuchet.fields()):
    failures.append("fields() lacks L4")

# Monte Carlo: the samples as arrays, their percentiles the report's.
mc = trebuchet.monte_carlo(dict(ca, M="3t..3.2t"), samples=300, seed=7)
done = program(VERIFY, "shot", "--L1", "4.13m", "--L2", "0.88m", "--F", "2/3", "--L4", "3.55m", "--M", "3t..3.2t", "--m", "50kg", "--mb", "174kg",
               "--samples", "300", "--seed", "7", "--format", "json")
theirs = json.loads(done.stdout)
for key in ("percentiles", "worked"):
    compare("monte carlo", {key: mc[key]}, {key: theirs[key]})
if mc["samples_R"].shape != (300,) or not np.all(np.isfinite(mc["samples_R"])):
    failures.append("monte carlo: samples_R is not 300 finite ranges")
# The drawn inputs beside the outputs: each M within its range, and the same as the program's.
if mc["draws"]["M"].shape != (300,) or not np.all((mc["draws"]["M"] >= 3000) & (mc["draws"]["M"] <= 3200)):
    failures.append("monte carlo: draws of M are not 300 values from 3 t to 3.2 t")
if list(mc["draws"]["M"]) != theirs["draws"]["--M"]:
    failures.append("monte carlo: the drawn M differ from the program's")
# A claim's odds from the arrays themselves.
claimed = trebuchet.monte_carlo(dict(ca, M="3t..3.2t"), samples=300, seed=7, claim="150m")
if claimed["claim"]["reached"] != int(np.sum(claimed["samples_R"] >= 150)):
    failures.append("monte carlo: the claim's count differs from the samples reaching it")

for failure in failures:
    print("FAIL", failure)
print("python module:", "FAILED" if failures else "passed")
sys.exit(1 if failures else 0)
