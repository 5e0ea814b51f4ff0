"""Every record the programs write reads back as the same shot (issue 50): each record, given to
trebuchet-verify as its input, is shot again with the settings it carries, and the shot's
figures must agree bit for bit. Not a snapshot: both sides are today's program, and the test
fails if any engine value or setting is lost or rounded on the way (a lost wind or target level
moves R by metres, a rounded L4 moves its last digits). A Monte Carlo run's report reads back
as its run: the same draws and percentiles.

Usage: read_back.py VERIFY"""
import json
import shlex
import subprocess
import sys
import tempfile

VERIFY = sys.argv[1]
ENGINE = ["--L1", "6m", "--L2", "1.5m", "--L3", "2m", "--L4", "5m", "--M", "2000kg", "--m", "10kg", "--mb", "100kg"]
# The figures of a shot that any lost input or setting changes.
FIGURES = ["R", "T", "R_vacuum", "eps", "Q", "v", "t_release", "pin_angle_at_release_deg", "sling_tension", "pivot_force", "rupture_margin"]
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
contest = run(["contest", "--m", "0.5kg", "--D", "5cm", "--max-width", "3m", "--max-height", "3m", "--max-M", "300kg"])[0]
read_back("contest", contest)
# Issue 63: compare reads a contest's record with its limits and measures each column against
# them. The contest's own engine (the hinged column, first) meets them: the same shot measured
# by the same rule; every shot column says whether it breaks any.
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(contest, f)
columns, notes = run(["compare", f.name])
measured = [c for c in columns if "error" not in c]
print(f"compare under the contest's limits: {[(c['within_limits'], [b['key'] for b in c['breaks']]) for c in measured]}")
if not (columns[0].get("within_limits") is True and all("within_limits" in c for c in measured) and "limits of the contest" in notes):
    failures.append("compare under a contest record's limits")
calibration = run(["calibrate", "--L1", "2.4m", "--L2", "0.6m", "--L3", "0.5m", "--M", "300kg", "--m", "4kg", "--mb", "30kg", "--axle-radius", "2.5cm", "--hinge-radius", "1.5cm", "--measured", "95m±3m", "--L4", "2.2m", "--target-level", "2m"])[0]
read_back("calibrate", calibration, lambda r: r["shot"])
# Issue 62: calibrate over unknowns carries its run (version, engine, settings, unknowns, samples,
# seed) and reads back as that run: the same draws, so the same percentiles and verdict.
over_unknowns = run(["calibrate", "--L1", "2.4m", "--L2", "0.6m", "--L3", "0.5m", "--M", "300kg", "--m", "4kg", "--mb", "30kg", "--axle-radius",
                     "2cm..3cm", "--hinge-radius", "1.5cm", "--measured", "95m±3m", "--L4", "2.2m", "--target-level", "2m", "--samples", "20",
                     "--seed", "7"])[0]
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(over_unknowns, f)
again, _ = run([f.name])
same = {k: v for k, v in again.items() if k != "wall_time_s"} == {k: v for k, v in over_unknowns.items() if k != "wall_time_s"}
print("calibrate over unknowns read back as the same run:", same, "; its version:", over_unknowns.get("version"))
if not same or "version" not in over_unknowns or over_unknowns["design"].get("seed") != 7:
    failures.append("calibrate over unknowns: its report did not read back as the same run")
sweep = run(["sweep", *ENGINE, "--vary", "L4=0m..8m", "--points", "3", "--range-from", "release"])[0]
read_back("sweep points", sweep["points"])
read_back("sweep record", sweep)  # the record itself reads as its points
read_back("compare", run(["compare", *ENGINE])[0])
WHIPPER = ["--machine", "whipper", "--L1", "4m", "--L2", "2m", "--L3", "4m", "--L4", "4m", "--M", "100kg", "--m", "3kg", "--mb", "10kg",
           "--H", "5m", "--projectile-diameter", "0.2m", "--rope-angle", "12", "--release-angle", "45"]
whipper, _ = run(WHIPPER)
read_back("whipper", whipper)
# The whipper's ball is sized by its diameter; in air the record also writes its density.
read_back("whipper in air", run([*WHIPPER, "--air"])[0])
# A beam of another wood's strength: its margin reads back.
read_back("modulus of rupture", run([*ENGINE, "--rupture", "60MPa"])[0])
# A sweep of L1 whose first point fails: that point fails again, not read as a design.
read_back("sweep of L1", run(["sweep", *ENGINE, "--vary", "L1=0m..8m", "--points", "3"])[0])
# The verifier's own CSV, with 17 digits, carries its release criterion, target level and range_from.
with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
    written = subprocess.run([VERIFY, *ENGINE, "--target-level", "3m", "--quality", "range", "--range-from", "release", "--rupture", "60MPa",
                              "--digits", "17",
                              "--format", "csv"], capture_output=True, text=True, check=True).stdout
    f.write(written)
again = subprocess.run([VERIFY, f.name, "--digits", "17", "--format", "csv"], capture_output=True, text=True).stdout
# A file's shots add the "error" column, last.
same = [line.rsplit(",", 1)[0] for line in again.splitlines()] == written.splitlines()
print("CSV with its settings read back the same:", same)
if not same:
    failures.append("the CSV of a shot with a target level, the range's release and range_from did not read back the same")

# A flag beside a record replaces its value, with a note.
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(shot, f)
changed, said = run([f.name, "--L4", "4.5m"])
print("--L4 beside the record:", said.strip())
if "--L4 4.5 m replaces design.L4 = 5 m" not in said or changed["engine"]["L4"] != 4.5 or changed["assumptions"] != shot["assumptions"]:
    failures.append("a flag beside a record: no note, or the value or the settings were lost")

# Flags that change a record's geometry: its written F goes, its L3 stays (a hinged record) and
# the whipper keeps its own H.
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(run(ENGINE)[0], f)
for flag in (["--L1", "6.5m"], ["--L2", "1.6m"], ["--theta", "40"], ["--H", "4m"]):
    changed, _ = run([f.name, *flag])
    if changed["engine"]["L3"] != 2.0:
        failures.append(f"{flag[0]} over a hinged record: L3 {changed['engine']['L3']}")
# A sweep over a record varies its geometry as the flag would: every point shoots.
for vary in ("L1=5m..7m", "L2=1m..2m", "theta_i_deg=20..40"):
    swept, _ = run(["sweep", f.name, "--vary", vary, "--points", "3"])
    if any("error" in point for point in swept["points"]):
        failures.append(f"sweep {vary} over a hinged record: a point failed")
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(whipper, f)
changed, _ = run([f.name, "--L1", "4.5m"])
if changed["engine"]["H"] != 5.0:
    failures.append(f"--L1 over a whipper record: H {changed['engine']['H']}, not the record's 5 m")

# One detail of the air over a record in air keeps the others; --air=false turns it off.
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(shot, f)
calm, said = run([f.name, "--wind", "0m/s"])
expected = dict(shot["assumptions"]["air"], wind=0.0)
print("--wind 0m/s over the record's air:", calm["assumptions"]["air"], said.strip())
if calm["assumptions"]["air"] != expected or calm["assumptions"]["target_level"] != shot["assumptions"]["target_level"]:
    failures.append("--wind over a record in air: the other details or settings were lost")
if "--wind 0 m/s replaces design.wind = 3 m/s" not in said:
    failures.append("--wind over a record in air: no note of the wind it replaces")
still, _ = run([f.name, "--air=false"])
if still["assumptions"]["air"] != "vacuum":
    failures.append("--air=false over a record in air did not shoot it in vacuum")
# A constant Cd over a record's Cd(Re), and the sling's drag turned off, shoot as from flags.
for record_flags, over, fresh in ((["--air", "--cd", "Re"], ["--cd", "0.47"], ["--air", "--cd", "0.47"]),
                                  (["--air", "--drag-in-sling"], ["--drag-in-sling=false"], ["--air"])):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(run([*ENGINE, *record_flags])[0], f)
    if run([f.name, *over])[0]["R"] != run([*ENGINE, *fresh])[0]["R"]:
        failures.append(f"{' '.join(over)} over a record shot with {' '.join(record_flags)}: not the shot of {' '.join(fresh)}")
# A CSV row shot in air describes its air but cannot give it: refused, unless the flags give one.
with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
    f.write(subprocess.run([VERIFY, *ENGINE, "--air", "--format", "csv"], capture_output=True, text=True, check=True).stdout)
refused = subprocess.run([VERIFY, f.name], capture_output=True, text=True)
given = subprocess.run([VERIFY, f.name, "--air"], capture_output=True, text=True)
print("a CSV row in air:", refused.returncode, refused.stderr.strip())
if refused.returncode != 2 or "--air=false" not in refused.stderr or given.returncode != 0:
    failures.append("a CSV row shot in air: not refused by name, or refused although --air was given")

# A Monte Carlo run's report reads back as its run: its "design" gives the ranges and spreads as
# text, the settings (a spread wind in its air, the target level, a given release) and the run's
# samples, seed and claim, so the same draws come again, bit for bit, on one thread as on two.
# The draws are compared column by column: the flags' run names them "--M", the file's "M".
# The file's keys come in another order than the table's (JSON's "axle_friction" before "mb");
# the run draws in the table's either way.
SPREADS = ["--mb", "90kg..110kg", "--M", "1900kg..2100kg", "--L4", "5m±0.1m", *ENGINE[:6], "--m", "10kg", "--air", "--wind", "1m/s..3m/s",
           "--axle-friction", "0.05..0.15", "--axle-radius", "2cm",
           "--target-level", "-3m", "--release-angle", "40", "--samples", "300", "--seed", "7", "--claim", "440m", "--threads", "2"]
report, _ = run(SPREADS)
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(report, f)
again, _ = run([f.name, "--threads", "1"])
same_draws = [again["draws"][k] for k in again["draws"]] == [report["draws"][k] for k in report["draws"]]
print(f"Monte Carlo report: R p50 {report['percentiles']['R']['p50']!r} read back as {again['percentiles']['R']['p50']!r}; "
      f"draws the same: {same_draws}; claim {report['claim']['probability']!r} read back as {again['claim']['probability']!r}")
for key in ("percentiles", "design", "samples", "seed", "failures", "assumptions", "air"):
    if again[key] != report[key]:
        failures.append(f"Monte Carlo report: {key} differs when read back")
if not same_draws or again["claim"]["probability"] != report["claim"]["probability"]:
    failures.append("Monte Carlo report: its draws or its claim's odds differ when read back")
# Flags over a report's spread settings: Cd(Re) replaces a spread Cd and --air=false the air's
# spreads, and what they run reads back as itself; flags that leave nothing to draw are refused.
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(run([*ENGINE[:8], *ENGINE[10:], "--air", "--cd", "0.4..0.5", "--air-density", "1.1..1.3", "--M", "1.9t..2.1t", "--samples", "30"])[0], f)
for over in (["--cd", "Re"], ["--air=false"]):
    changed, _ = run([f.name, *over])
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as g:
        json.dump(changed, g)
    if run([g.name])[0]["percentiles"] != changed["percentiles"]:
        failures.append(f"{over[0]} over a Monte Carlo report: the run it made does not read back as itself")
    print(f"{' '.join(over)} over a report: draws {[u['option'] for u in changed['uncertain']]}")
fixed = subprocess.run([VERIFY, f.name, "--M", "2t", "--cd", "0.45", "--air-density", "1.2"], capture_output=True, text=True)
if fixed.returncode != 2 or "nothing is left to draw" not in fixed.stderr:
    failures.append("flags that fix every spread of a report: not refused")
# complete's run takes its attested values as flags: its report says which, and they run it again.
completion, _ = run(["complete", "--Lb", "9.5m", "--M", "2.5t..3.5t", "--m", "50kg", "--air", "--wind", "0..4m/s", "--target-level", "5m",
                      "--samples", "20", "--seed", "123456789012345678"])
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump(completion, f)
said = subprocess.run([VERIFY, f.name], capture_output=True, text=True)
command = said.stderr.split("run it again with trebuchet-verify ", 1)[-1].strip()
print("complete's Monte Carlo report:", said.returncode, command)
if said.returncode != 2 or not command.startswith("complete "):
    failures.append("complete's Monte Carlo report: not refused with the flags that run it again")
else:
    rerun, _ = run(shlex.split(command))
    if rerun["percentiles"] != completion["percentiles"] or rerun["attested"] != completion["attested"]:
        failures.append("complete's Monte Carlo report: its flags do not run the same run again")

if failures:
    print("FAILED:", *failures, sep="\n  ")
    sys.exit(1)
print("every record read back as the same shot")
