"""Every record the programs write reads back as the same shot (issue 50): each record, given to
trebuchet-verify as its input, is shot again with the settings it carries, and the shot's
figures must agree bit for bit. Not a snapshot: both sides are today's program, and the test
fails if any engine value or setting is lost or rounded on the way (a lost wind or target level
moves R by metres, a rounded L4 moves its last digits).

Usage: read_back.py VERIFY"""
import json
import subprocess
import sys
import tempfile

VERIFY = sys.argv[1]
ENGINE = ["--L1", "6m", "--L2", "1.5m", "--L3", "2m", "--L4", "5m", "--M", "2000kg", "--m", "10kg", "--mb", "100kg"]
# The figures of a shot that any lost input or setting changes.
FIGURES = ["R", "T", "R_vacuum", "eps", "Q", "v", "t_release", "pin_angle_at_release_deg", "sling_tension", "pivot_force"]
failures = []


def run(args, expect=(0,)):
    out = subprocess.run([VERIFY, *args, "--format", "json"], capture_output=True, text=True)
    if out.returncode not in expect:
        raise SystemExit(f"{' '.join(args)}: exit {out.returncode}\n{out.stderr}")
    return json.loads(out.stdout), out.stderr


def read_back(name, record, shot_of=lambda r: r):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(record, f)
    again, _ = run([f.name], expect=(0, 1, 2, 3))
    written = record["points"] if isinstance(record, dict) and "vary" in record else record
    pairs = list(zip(written, again)) if isinstance(written, list) else [(written, again)]
    for i, (before, after) in enumerate(pairs):
        before = shot_of(before)
        if "error" in before:
            ok = "error" in after
            print(f"{name}[{i}]: failed as written, and again: {ok}")
            if not ok:
                failures.append(f"{name}[{i}]")
            continue
        differ = [k for k in FIGURES if before.get(k) != after.get(k)]
        print(f"{name}[{i}]: R {before['R']!r} read back as {after.get('R')!r}; figures that differ: {differ or 'none'}")
        if differ:
            failures.append(f"{name}[{i}]: {differ}")
    return again


shot, _ = run([*ENGINE, "--air", "--wind", "3m/s", "--release-angle", "40", "--target-level", "-3m", "--axle-friction", "0.1",
               "--axle-radius", "2cm", "--rtol", "1e-10"])
again = read_back("shot in air, a given release, a target level, friction", shot)
if again != shot:  # the whole record, not only its figures
    failures.append("shot: the record read back differs from the record")
read_back("fit", run(["fit", *ENGINE, "--R", "500m", "--T", "30kJ"])[0])
read_back("optimize", run(["optimize", "--R", "300m", "--T", "50kJ", "--range-from", "release"])[0])
read_back("complete in air", run(["complete", "--Lb", "9.5m", "--M", "3t", "--m", "50kg", "--air", "--target-level", "5m"])[0])
read_back("contest", run(["contest", "--m", "0.5kg", "--D", "5cm", "--max-width", "3m", "--max-height", "3m", "--max-M", "300kg"])[0])
calibration = run(["calibrate", "--L1", "2.4m", "--L2", "0.6m", "--L3", "0.5m", "--M", "300kg", "--m", "4kg", "--mb", "30kg", "--axle-radius", "2.5cm", "--hinge-radius", "1.5cm", "--measured", "95m±3m", "--L4", "2.2m", "--target-level", "2m"])[0]
read_back("calibrate", calibration, lambda r: r["shot"])
sweep = run(["sweep", *ENGINE, "--vary", "L4=0m..8m", "--points", "3", "--range-from", "release"])[0]
read_back("sweep points", sweep["points"])
read_back("sweep record", sweep)  # the record itself reads as its points
read_back("compare", run(["compare", *ENGINE])[0])
whipper, _ = run(["--machine", "whipper", "--L1", "4m", "--L2", "2m", "--L3", "4m", "--L4", "4m", "--M", "100kg", "--m", "3kg", "--mb", "10kg",
                  "--H", "5m", "--projectile-diameter", "0.2m", "--rope-angle", "12", "--release-angle", "45"])
read_back("whipper", whipper)

# A flag beside a record replaces its value, with a note.
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(shot, f)
changed, said = run([f.name, "--L4", "4.5m"])
print("--L4 beside the record:", said.strip())
if "--L4 4.5 m replaces design.L4 = 5 m" not in said or changed["engine"]["L4"] != 4.5 or changed["assumptions"] != shot["assumptions"]:
    failures.append("a flag beside a record: no note, or the value or the settings were lost")

if failures:
    print("FAILED:", *failures, sep="\n  ")
    sys.exit(1)
print("every record read back as the same shot")
