#!/usr/bin/env python3
"""extremes.py VERIFY [PYTHONPATH]: every numeric input at its extremes (issue 34).

The inputs are read from the programs themselves, not listed here: every option of each
subcommand's --help that takes a value, and every key of a design as the verifier writes it
(`shot --format json`'s engine, with the parts as built). Each is given 0, -0, the smallest
subnormal, 1e-308, 1e308, inf, nan and a negative number:
  - as a flag of shot, calibrate, complete, optimize and fit;
  - as a key of a JSON design and as a column of a CSV design;
  - as a key of the Python module's shot (when the module is on PYTHONPATH).
A case passes when it ends by itself within its time (never a signal, never a hang), with an
exit code the programs document (0, 1, 2 or 3), and no nan or inf in its output outside a
quoted echo of the input. Either an answer or a named refusal: what the answer is, the corpus
(corpus.tsv) and the physics tests check.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

VERIFY = os.path.realpath(sys.argv[1])
PYTHONPATH = sys.argv[2] if len(sys.argv) > 2 else None
VALUES = ["0", "-0", "5e-324", "1e-308", "1e308", "inf", "nan", "-1"]
# A run of the programs: a complete's search in hostile air takes seconds (docs/stability.md).
LIMIT_S = 60

ENGINE = ["--L1", "4.13m", "--L2", "0.88m", "--F", "2/3", "--L4", "3.55m", "--M", "3.11t", "--m", "50kg", "--mb", "174kg"]
BASES = {
    "shot": ENGINE,
    "fit": ENGINE + ["--R", "150m", "--T", "38kJ"],
    "calibrate": ENGINE + ["--axle-radius", "5cm", "--hinge-radius", "3cm", "--measured", "139m±1m"],
    "complete": ["--Lb", "9.5m", "--M", "3t", "--m", "50kg"],
    "optimize": ["--R", "450m", "--T", "232kJ"],
}
# Options that take no number: files and folders written, and switches.
NOT_NUMBERS = {"--series", "--plot", "--help", "-h"}
NONFINITE = re.compile(r"(?<![A-Za-z_])-?(nan|inf)(?![A-Za-z_])", re.IGNORECASE)


def unquoted(text):
    text = re.sub(r"'[^']*'", "", text)
    text = re.sub(r'"[^"]*"', "", text)
    return re.sub(r"(was|were) not expected: .*", "", text)


def value_options(sub):
    help_text = subprocess.run([VERIFY, sub, "--help"], capture_output=True, text=True, check=True).stdout
    options = []
    for line in help_text.splitlines():
        m = re.match(r"\s+(--[\w-]+) (TEXT|FLOAT|INT)", line)
        if m and m.group(1) not in NOT_NUMBERS:
            options.append(m.group(1))
    return options


def with_option(base, option, value):
    args = list(base)
    if option in args:
        i = args.index(option)
        del args[i:i + 2]
    return args + [option, value]


def run(args, stdin=None, cwd=None):
    try:
        p = subprocess.run([VERIFY] + args, capture_output=True, text=True, timeout=LIMIT_S, input=stdin, cwd=cwd)
    except subprocess.TimeoutExpired:
        return f"did not finish within {LIMIT_S} s"
    out = p.stdout + p.stderr
    if p.returncode < 0:
        return f"ended by signal {-p.returncode}"
    if p.returncode not in (0, 1, 2, 3):
        return f"exit {p.returncode}, not a documented code"
    if "terminate called" in out or "Aborted" in out:
        return "aborted"
    if NONFINITE.search(unquoted(out)):
        return "nan or inf in the output: " + NONFINITE.search(unquoted(out)).group(0) + " in " + out.strip()[:300]
    return None


def design_keys():
    """The keys of a design as the verifier writes them, parts as built included."""
    out = subprocess.run([VERIFY] + ENGINE + ["--axle-friction", "0.1", "--axle-radius", "5cm", "--beam-cm", "1m", "--beam-inertia", "1500",
                                              "--counterweight-inertia", "300", "--format", "json"],
                         capture_output=True, text=True, check=True).stdout
    engine = json.loads(out)["engine"]
    return engine


def main():
    cases = []  # (description, thunk)
    with tempfile.TemporaryDirectory() as work:
        for sub, base in BASES.items():
            for option in value_options(sub):
                for value in VALUES:
                    args = [sub] + with_option(base, option, value) + (["--threads", "1"] if sub in ("shot", "complete") and option != "--threads" else [])
                    cases.append((f"{sub} {option} {value}", lambda args=args: run(args, cwd=work)))
        engine = design_keys()
        derived = {"Lb", "H", "l", "l4", "L", "mu", "mu_b", "K", "DeltaU"}
        for key in engine:
            if key in derived:
                continue
            for value in VALUES:
                number = float(value)
                design = dict(engine, **{key: number})
                text = json.dumps(design)  # inf and nan as JSON's extension, which the reader refuses by name
                cases.append((f"JSON {key} {value}", lambda text=text: run(["-"], stdin=text, cwd=work)))
                header = ",".join(design)
                row = ",".join(repr(v) if not isinstance(v, str) else v for v in design.values())
                cases.append((f"CSV {key} {value}", lambda csv=header + "\n" + row + "\n": run(["-"], stdin=csv, cwd=work)))
        if PYTHONPATH:
            sys.path.insert(0, PYTHONPATH)
            import trebuchet  # noqa: E402

            def python_case(key, value):
                try:
                    answer = trebuchet.shot(dict(engine, **{key: float(value)}))
                    text = json.dumps(answer, allow_nan=True)
                except trebuchet.TrebuchetError as e:
                    text = str(e)
                except Exception as e:  # anything else is a defect: a raw error instead of a named refusal
                    return f"{type(e).__name__}: {e}"
                found = NONFINITE.search(unquoted(text))
                return "nan or inf in the answer: " + text[:300] if found else None

            for key in engine:
                if key in derived:
                    continue
                for value in VALUES:
                    cases.append((f"Python {key} {value}", lambda key=key, value=value: python_case(key, value)))

        with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            results = list(pool.map(lambda case: (case[0], case[1]()), cases))
    failed = [(name, problem) for name, problem in results if problem]
    for name, problem in failed:
        print(f"FAILED {name}: {problem}")
    print(f"{len(results) - len(failed)} passed, {len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
