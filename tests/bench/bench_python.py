"""A benchmark, not a test: 10^4 shots of Alcala la Vieja Ca from Python through the module,
against the same 10^4 through trebuchet-verify (one run over a JSON array of them, one thread),
and single shots as whole program runs. Medians of 5 repeats; the per-call overhead is the
module's time per shot less the program's within its batch.
Usage: PYTHONPATH=build/python /usr/bin/python3 tests/bench/bench_python.py build/verify/trebuchet-verify"""
import json
import statistics
import subprocess
import sys
import tempfile
import time

import trebuchet

VERIFY = sys.argv[1]
N = 10000
ca = {"L1": 4.13, "L2": 0.88, "F": 2 / 3, "L4": 3.55, "M": 3110, "m": 50, "mb": 174}


def median_seconds(work, repeats=5):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


module = median_seconds(lambda: [trebuchet.shot(ca) for _ in range(N)])
with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    json.dump([ca] * N, f)
program = median_seconds(lambda: subprocess.run([VERIFY, "shot", f.name, "--format", "json", "--threads", "1"], check=True, capture_output=True))
single = median_seconds(lambda: [subprocess.run([VERIFY, "shot", "--L1", "4.13m", "--L2", "0.88m", "--F", "2/3", "--L4", "3.55m", "--M", "3.11t",
                                                 "--m", "50kg", "--mb", "174kg", "--format", "json"], check=True, capture_output=True) for _ in range(100)])
print(f"module: {N} shots in {module:.3f} s, {module / N * 1e3:.4f} ms a shot")
print(f"program, one run over {N} designs (--threads 1): {program:.3f} s, {program / N * 1e3:.4f} ms a shot")
print(f"program, a run a shot: {single / 100 * 1e3:.3f} ms a shot")
print(f"per-call overhead of the module: {(module - program) / N * 1e3:.4f} ms ({module / program:.2f}x the batch)")

# The Monte Carlo (issue 38): per sample through the module on one thread, against the program's
# own run of the same samples on one thread; and how long Ctrl-C takes to stop the largest run
# (tests/python/interrupt.py, goal 0.2 s), over 5 runs.
uncertain = dict(ca, M="2.9t..3.3t")
SAMPLES = 20000
module_mc = median_seconds(lambda: trebuchet.monte_carlo(uncertain, samples=SAMPLES, threads=1))
program_mc = median_seconds(lambda: subprocess.run([VERIFY, "shot", "--L1", "4.13m", "--L2", "0.88m", "--F", "2/3", "--L4", "3.55m", "--M", "2.9t..3.3t",
                                                    "--m", "50kg", "--mb", "174kg", "--samples", str(SAMPLES), "--threads", "1", "--format", "json"],
                                                   check=True, capture_output=True))
print(f"Monte Carlo, one thread: module {module_mc / SAMPLES * 1e6:.1f} us a sample, program {program_mc / SAMPLES * 1e6:.1f} us a sample "
      f"({module_mc / program_mc:.2f}x)")
stops = []
for _ in range(5):
    done = subprocess.run([sys.executable, __file__.replace("bench/bench_python.py", "python/interrupt.py")], capture_output=True, text=True, check=True)
    stops.append(float(done.stdout.split()[1]))
print(f"Ctrl-C stops the largest Monte Carlo run in {statistics.median(stops) * 1e3:.1f} ms (median of 5; worst {max(stops) * 1e3:.1f} ms)")
