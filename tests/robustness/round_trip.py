#!/usr/bin/env python3
"""round_trip.py VERIFY: what the verifier writes, it reads back (issue 34).

For every kind of engine (the paper's, propped, a beam given by its centre of mass and inertia
or radius of gyration, a tapered beam, a beam of a given diameter, a box counterweight or one
with its inertia, friction at each pin and in the trough, a rope in the air before the release,
a release given by its pin angle, velocity angle or time, the fixed counterweight, the
floating arm and the whipper on its frame):
  - the `engine` member of `shot --format json`, fed back as a design, gives the same record,
    every number equal to the last bit (JSON numbers are written to round-trip doubles);
  - the CSV of `shot --format csv --digits 17`, fed back, gives the same row (with the "error"
    column that a CSV input adds to the output).
"""
import csv
import io
import json
import os
import subprocess
import sys
import tempfile

VERIFY = os.path.realpath(sys.argv[1])
ENGINE = ["--L1", "4.13m", "--L2", "0.88m", "--F", "2/3", "--L4", "3.55m", "--M", "3.11t", "--m", "50kg"]
KINDS = {
    "ideal": ["--mb", "174kg"],
    "propped": ["--mb", "174kg", "--psi-i", "10"],
    "diameter": ["--D", "30cm"],
    "beam_inertia": ["--mb", "174kg", "--beam-cm", "1m", "--beam-inertia", "1500"],
    "beam_gyration": ["--mb", "174kg", "--beam-cm", "1m", "--beam-gyration", "2.5m"],
    "tapered": ["--D-hinge", "40cm", "--D-tip", "20cm"],
    "box": ["--mb", "174kg", "--box-width", "1m", "--box-height", "0.8m"],
    "counterweight_inertia": ["--mb", "174kg", "--counterweight-inertia", "400"],
    "friction": ["--mb", "174kg", "--axle-friction", "0.1", "--axle-radius", "5cm", "--hinge-friction", "0.12", "--hinge-radius", "3cm",
                 "--trough-friction", "0.2"],
    "rope": ["--mb", "174kg", "--rope-diameter", "2cm", "--rope-cd", "1.1", "--air", "--drag-in-sling"],
    "pin_angle": ["--mb", "174kg", "--pin-angle", "30"],
    "release_angle": ["--mb", "174kg", "--release-angle", "40"],
    "release_time": ["--mb", "174kg", "--release-time", "1s"],
    "fixed": ["--mb", "174kg", "--machine", "fixed", "--counterweight-inertia", "300"],
    "floating_arm": ["--mb", "174kg", "--machine", "floating-arm"],
    "whipper": ["--mb", "10kg", "--machine", "whipper", "--H", "5.5m", "--rope-angle", "12", "--projectile-diameter", "25cm"],
}
# The whipper on pytrebuchet's default parts: the paper's engines' short arm L3 would turn it backwards.
ENGINE_OF = {"whipper": ["--L1", "4m", "--L2", "2m", "--L3", "4m", "--L4", "4m", "--M", "100kg", "--m", "3kg"]}
SETTINGS_FLAGS = {"--air", "--drag-in-sling"}


def verify(args, cwd):
    p = subprocess.run([VERIFY] + args, capture_output=True, text=True, cwd=cwd)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(args)}: exit {p.returncode}: {p.stderr.strip()}")
    return p.stdout


def main():
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        for kind, flags in KINDS.items():
            settings = [f for f in flags if f in SETTINGS_FLAGS]
            engine = ENGINE_OF.get(kind, ENGINE)
            record = json.loads(verify(engine + flags + ["--format", "json"], work))
            with open(os.path.join(work, "engine.json"), "w") as f:
                json.dump(record["engine"], f)
            again = json.loads(verify(["engine.json", "--format", "json"] + settings, work))
            json_same = again == record

            table = verify(engine + flags + ["--format", "csv", "--digits", "17"], work)
            with open(os.path.join(work, "engine.csv"), "w") as f:
                f.write(table)
            read_back = verify(["engine.csv", "--format", "csv", "--digits", "17"] + settings, work)
            first = list(csv.DictReader(io.StringIO(table)))
            second = list(csv.DictReader(io.StringIO(read_back)))
            csv_same = len(first) == len(second) == 1 and all(second[0].get(k) == v for k, v in first[0].items()) and second[0]["error"] == ""
            print(f"{kind}: JSON {'same' if json_same else 'DIFFERS'}, CSV {'same' if csv_same else 'DIFFERS'}")
            failures += (not json_same) + (not csv_same)
    print(f"{2 * len(KINDS) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
