"""trebuchet: design and check swinging-counterweight trebuchets (Horsdal's model).

The same library as the programs trebuchet-calc and trebuchet-verify: each function takes the
programs' keys (docs/schema.md) as keyword arguments, values as SI floats or strings with a unit
("150m", "3.1t"), and returns the programs' JSON record as a dict; a shot's series and a Monte
Carlo run's samples come as NumPy arrays. A refused request raises TrebuchetError with the
programs' message. docs/python.md has the reference.
"""
import concurrent.futures
import json
import numbers
import os
import signal
import sys
import threading
import warnings

import numpy as np

from . import _trebuchet

__all__ = ["TrebuchetError", "TrebuchetWarning", "design", "shot", "fit", "optimize", "sweep", "complete", "compare", "contest", "monte_carlo", "fields",
           "settings", "to_frame", "__version__", "__commit__"]

__version__ = _trebuchet.version
"""The project's version, PEP 440: what a notebook records beside the numbers it got."""
__commit__ = _trebuchet.commit
"""The commit the module is built from (git describe), as trebuchet-verify --version prints it."""


_MAX_THREADS = 65536  # settings.def's row of --threads: "1 or more (at most 65536)"


class TrebuchetError(ValueError):
    """A request the library refuses: the programs' message, its kind (docs/exit_codes.md) and
    the keys it names."""

    def __init__(self, message, kind, names):
        super().__init__(message)
        self.kind = kind
        self.names = names


class TrebuchetWarning(UserWarning):
    """Where the model stops holding, or an answer needs a caveat: the programs' warning text,
    also kept in the record's "warnings"."""


_MAX_DEPTH = 64  # a request is a few levels deep; the library's JSON reader refuses much less than Python's recursion limit


def _plain(value, path, depth=0):
    """A request's value as JSON takes it: finite numbers (Python's, NumPy's scalars), texts with
    units, True/False, and dicts (keyed by texts) and lists of them. Any other type or key is a
    TypeError naming its path;
    NaN or infinity, or a structure that nests too deep or holds itself, a TrebuchetError naming it."""
    if depth > _MAX_DEPTH:
        raise TrebuchetError(f"{path or 'the request'} nests lists or dicts more than {_MAX_DEPTH} levels deep (or holds itself); "
                             "give a design's keys with values", "usage", [path.split(".")[0].split("[")[0]] if path else [])
    if isinstance(value, dict):
        for key in value:
            if not isinstance(key, str):
                raise TypeError(f"{path or 'the request'}: the key {key!r} is not a text but of type {type(key).__name__}; give each key as a text, such as \"L1\"")
        return {key: _plain(v, f"{path}.{key}" if path else key, depth + 1) for key, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v, f"{path}[{i}]", depth + 1) for i, v in enumerate(value)]
    if value is None or isinstance(value, (str, bool)):
        return value
    if isinstance(value, np.generic) and value.shape == ():
        value = value.item()
    if isinstance(value, numbers.Real):
        if not isinstance(value, (int, bool)) and not np.isfinite(float(value)):
            key = path.rsplit(".", 1)[-1] if path else ""
            raise TrebuchetError(f"{path or 'the request'}: '{float(value)}' is not a finite number; give a finite number", "bad_number",
                                 [key] if key else [])
        return float(value) if not isinstance(value, (int, bool)) else value
    raise TypeError(f"{path or 'the request'}: a {type(value).__name__} is not a value; give a number, or a text with its unit such as \"3.1t\"")


def _warn(record):
    """The record's warnings through warnings.warn, where a notebook shows them and a test can
    turn them into errors; and each key the library passed through unread, by name."""
    if isinstance(record, dict):
        for text in record.get("warnings", []) or []:
            warnings.warn(text, TrebuchetWarning, stacklevel=3)
        for key in record.get("passed", {}) or {}:
            warnings.warn(f"{key}: passed through unread, as a value of your own (a site, a comment, your notes); a value meant for "
                          "the engine goes under its input's key (fields())", TrebuchetWarning, stacklevel=3)


def _refusal(answer):
    """The TrebuchetError of the library's error object ({"error", "kind", "names"}); None for any other answer."""
    if isinstance(answer, dict) and set(answer) == {"error", "kind", "names"}:
        return TrebuchetError(answer["error"], answer["kind"], answer["names"])
    return None


def _call(function, request):
    request = _plain(request, "")
    text = json.dumps(request, allow_nan=False)
    answer = json.loads(function(text))
    refused = _refusal(answer)
    if refused:
        raise refused
    for record in answer if isinstance(answer, list) else [answer]:
        _warn(record)
    return answer


def _arrays(record):
    """Lists of numbers (None for no value) as float arrays (NaN for no value); other lists stay."""
    for key, value in record.items():
        if isinstance(value, list) and value and all(v is None or isinstance(v, (int, float)) for v in value):
            record[key] = np.array([np.nan if v is None else v for v in value], dtype=float)
    return record


def design(**givens):
    """The calculator's optimal engine for two givens, e.g. design(R="150m", m="50kg")."""
    return _call(_trebuchet.design, givens)


def _input_names(operation):
    """Each input's names (its key, then its aliases) that a keyword argument may give over a
    design or attested values: every row of fields() that `operation` takes, less the capacity
    (fit's own arguments) and the material (a key of the request itself)."""
    rows = json.loads(_trebuchet.fields("{}"))["fields"]
    return [[row["key"], *row["aliases"]] for row in rows if operation in row["operations"] and row["group"] not in ("capacity", "material")]


_SHOT_INPUTS = _input_names("shot")
_COMPLETE_INPUTS = _input_names("complete")


def _over(settings, inputs, **more):
    """The request's "over": each keyword argument that gives one of `inputs` (and `more`), taken
    out of `settings`. The library lays it over the design's own as the programs' flags go over
    a file's (a value replaces the one given under any of its names, a release the one given in
    any form, L3 the F); empty when none is given."""
    over = {name: settings.pop(name) for names in inputs for name in names if name in settings}
    over.update(more)
    return {"over": over} if over else {}


def shot(design, *, series=False, **settings):
    """One shot of an engine: a dict of the programs' keys (fields(), docs/inputs.md), or any
    record the programs or this module wrote (a shot, fit, optimum, completion, contest, sweep
    point), which is shot again with its own settings.

    Each input of the design (fields(): L4, rope_mass, ...) may also be given as a keyword here,
    over the design's own, as the programs' flags go over a file's.
    The release: at the optimum of `quality` unless the engine sets one, by release_time [s],
    release_angle_deg (the projectile's velocity angle, VirtualTrebuchet's) or pin_angle_deg (the
    pin a builder bends), each in the design or as a keyword here. The machine: machine="hinged"
    (the default), "fixed", "floating-arm" or "whipper" (docs/machines.md), likewise.

    Settings, each under its flag's word (settings(), docs/inputs.md), over a record's own:
    quality ("Q", "eps", "range"; or release=), n, tol (or tolerance=), stepper, rtol, atol,
    target_level, range_from ("pivot", "release"), air (False, True or a dict of density,
    drag_coefficient, projectile_density, wind, drag_in_sling), or the air's details flat
    (air_density, cd, projectile, wind, drag_in_sling), and the material (g, youngs_modulus,
    wood_density, modulus_of_rupture) over the design's own.
    With series=True the answer's "series" holds the motion, its frames as arrays."""
    request = dict(settings, design=design, **_over(settings, _SHOT_INPUTS))
    if series:
        request["series"] = True
    answer = _call(_trebuchet.shot, request)
    if series:
        _arrays(answer["series"]["frames"])
        _arrays(answer["series"]["flight"])
        _arrays(answer["series"]["phase_two"])
    return answer


def fit(design, R, T, **settings):
    """The design's shape (l, l4, mu_b, theta_i, F) fitted in mu and size to the capacity R, T.
    Settings: those of shot."""
    return _call(_trebuchet.shot, dict(settings, design=design, fit=True, **_over(settings, _SHOT_INPUTS, R=R, T=T)))


def optimize(R, T=None, *, m=None, **options):
    """The ab-initio optimum for the capacity R with T (or with the stone's m): a list of the optima
    found (one, or one per branch at a fixed l). Options: theta_i_deg, F, l, the material and the
    settings of shot."""
    request = dict(options, R=R)
    if T is not None:
        request["T"] = T
    if m is not None:
        request["m"] = m
    return _call(_trebuchet.optimize, request)


def sweep(design, vary, *, points=21, **settings):
    """What if one value changes: the shot of the design at each of `points` values of `vary`
    ("L4=2m..5m": a value of the engine, its parts or its release, and its range), the rest held.
    The answer's "points" are shot records, the same as shot() of each engine, or {key, "error"}.
    The design and the settings: those of shot (a record too, with its own settings)."""
    return _call(_trebuchet.sweep, dict(settings, design=design, vary=vary, points=points, **_over(settings, _SHOT_INPUTS)))


def compare(design, **settings):
    """One engine's parts built as each machine, hinged, fixed, floating-arm and whipper, side by
    side (trebuchet-verify compare): a list of shot records, one a machine (its engine's
    "machine"), or {"machine", "error"} where a machine refuses the engine. Released where the
    range peaks unless quality= says otherwise. The design and the settings: those of shot, but
    the machine, which compare chooses."""
    if "machine" in settings:  # as the programs refuse compare --machine
        raise TrebuchetError("compare builds the engine as each machine in turn; leave out machine", "usage", ["machine"])
    return _call(_trebuchet.compare, dict(settings, design=design, **_over(settings, _SHOT_INPUTS)))


def contest(m, *, machine="hinged", **options):
    """The best engine of a machine for the projectile m within a contest's limits
    (trebuchet-verify contest): the beam by D (its diameter, of the wood) or mb_per_m (kg/m);
    the limits max_width, max_height, max_M, max_axle_load, max_acceleration and min_clearance;
    objective ("range" or "eps"), pareto (points of the front of range against the axle's load),
    theta_i_deg, box_width, box_height, the material and the air's settings. machine="all" gives
    a dict of each machine's best (or the TrebuchetError that machine refused with) by name; the
    whipper is not designed by search. A refusal every machine gives alike (bad input) is raised."""
    answer = _call(_trebuchet.contest, dict(options, m=m, machine=machine))
    if machine != "all":
        return answer
    best = {}  # each machine's best, or the TrebuchetError of the error object it was refused with
    for name, record in answer.items():
        best[name] = _refusal(record) or record
        if best[name] is record:
            _warn(record)
    return best


def complete(attested, **settings):
    """The best engine that keeps the attested values (Lb, L1, L2, H, L4, M, m, mb, D, l,
    theta_i_deg, F, ...); each may also be given as a keyword argument, over attested's own."""
    return _call(_trebuchet.complete, dict(settings, attested=attested, **_over(settings, _COMPLETE_INPUTS)))


def monte_carlo(design=None, *, attested=None, samples=None, seed=None, threads=None, progress=False, **settings):
    """A Monte Carlo run over values given as ranges ("2.5t..3.5t") or spreads ("3.5m±0.2m"), of
    shots (design) or completions (attested). The answer is the programs' report; its "draws"
    holds, as arrays over the samples in order, each drawn input under its key and R, T, eps and
    v (NaN where a sample failed), with "failure" the messages (None where it worked). With
    claim="300m", "claim" gives the fraction of samples that reach it. "samples_R", "samples_T",
    "samples_eps", "samples_v" are the draws' R, T, eps and v.

    The samples run in chunks on `threads` threads (default: the cores), each with the
    interpreter's lock released; the answer is the same on any number. Ctrl-C or a notebook's
    interrupt stops the run between chunks, with no thread left running, and raises
    KeyboardInterrupt. progress=True shows how many samples are done, on stderr.

    samples defaults to 10000 shots or 1000 completions, seed to 1. A run's report given back as
    its design (or attested) is the same run again: its ranges, spreads, settings, samples and
    seed, with the keywords given here over them."""
    if (design is None) == (attested is None):
        raise TrebuchetError("give a design (for shots) or attested values (for completions), one of them", "usage", ["design", "attested"])
    parts = sorted(set(settings) & {"first", "count", "outcomes"})
    if parts:
        raise TrebuchetError(f"{', '.join(parts)}: monte_carlo splits the run into parts itself; leave them out (samples= sets the run's size)",
                             "usage", parts)
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or threads < 1):
        raise TypeError(f"threads: {threads!r} is not a number of threads; give a whole number from 1 up, or None for the cores")
    if threads is not None and threads > _MAX_THREADS:  # the programs' --threads has the same bound
        raise TrebuchetError(f"threads: {threads} must be 1 or more (at most {_MAX_THREADS})", "usage", ["threads"])
    over = _over(settings, _SHOT_INPUTS if design is not None else _COMPLETE_INPUTS)  # a value, range or spread over the design's own
    request = dict(settings, **over)
    request.update({key: value for key, value in (("samples", samples), ("seed", seed)) if value is not None})
    key, given = ("design", design) if design is not None else ("attested", attested)
    # A run's report given back is sent as its run, the part a request gives (its draws are
    # arrays); the library reads it, and names the key to give it under if it is the other's.
    if isinstance(given, dict) and "uncertain" in given:
        given = {part: given[part] for part in ("uncertain", "design", "attested") if part in given}
    request[key] = given
    # The request checked once, before any thread starts; it answers with the run's samples.
    samples = _call(_trebuchet.monte_carlo, dict(request, first=0, count=0))["samples"]
    # A chunk is a few milliseconds of shots, or one completion (each a search of its own), so
    # that an interrupt waits for one chunk a thread at most.
    chunk = 1 if attested is not None else 16
    starts = list(range(0, int(samples), chunk))
    parts = [None] * len(starts)
    workers = int(threads or os.cpu_count() or 1)
    # Ctrl-C is taken as a flag and acted on between chunks, in this loop: a KeyboardInterrupt
    # raised inside the executor's own code could leave its lock held, and its shutdown waiting
    # for it for ever. (Only the main thread may set a signal's handler; elsewhere none is set.)
    interrupted = []
    main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGINT, lambda *_: interrupted.append(True)) if main else None
    done, next_chunk = 0, 0
    executor = concurrent.futures.ThreadPoolExecutor(max_workers=workers)
    pending = {}
    try:
        while next_chunk < len(starts) or pending:
            if interrupted:
                raise KeyboardInterrupt
            while next_chunk < len(starts) and len(pending) < 2 * workers:  # a few chunks ahead of the threads
                first = starts[next_chunk]
                text = json.dumps(_plain(dict(request, first=first, count=min(chunk, int(samples) - first)), ""))
                pending[executor.submit(_trebuchet.monte_carlo, text)] = next_chunk
                next_chunk += 1
            finished, _ = concurrent.futures.wait(pending, timeout=0.05, return_when=concurrent.futures.FIRST_COMPLETED)
            for future in finished:
                k = pending.pop(future)
                answer = json.loads(future.result())
                if isinstance(answer, dict) and set(answer) == {"error", "kind", "names"}:
                    raise TrebuchetError(answer["error"], answer["kind"], answer["names"])
                parts[k] = answer["outcomes"]
                done += len(parts[k])
            if progress:
                print(f"\rtrebuchet.monte_carlo: {done} of {samples} samples", end="", file=sys.stderr, flush=True)
    finally:  # on an interrupt too: the chunks not begun are dropped, those running finish
        executor.shutdown(wait=True, cancel_futures=True)
        if main:
            signal.signal(signal.SIGINT, previous)
        if progress:
            print(file=sys.stderr)
    outcomes = [outcome for part in parts for outcome in part]
    answer = _call(_trebuchet.monte_carlo, dict(request, outcomes=outcomes))
    for text in answer.get("notes", []):  # what reading the design left out (its capacity), as the programs' notes say
        warnings.warn(text, TrebuchetWarning, stacklevel=2)
    _arrays(answer["draws"])
    for name in ["R", "T", "eps", "v"]:
        answer["samples_" + name] = answer["draws"][name]
    return answer


def fields():
    """The table of inputs: a list of dicts, one per key a design, a completion or the calculator
    takes, with its aliases, flag, dimension, SI unit, accepted units, default, range and help."""
    return _call(_trebuchet.fields, {})["fields"]


def settings():
    """The table of settings: a list of dicts, one per keyword argument the functions take besides
    the engine's values (quality, tol, air, ...), with its aliases, the programs' flag, the requests
    that take it, default, range and help."""
    return _call(_trebuchet.fields, {})["settings"]


def _frame_row(record, machine=None):
    """A record as one row: its numbers and texts, then its engine's inputs beside them (L1, M,
    m, ...: what each row is), its machine, and why it warns or failed ("" where it did not)."""
    if isinstance(record, TrebuchetError):
        return {"machine": machine, "warnings": "", "error": str(record)}
    scalar = (bool, int, float, str)
    row = {k: v for k, v in record.items() if v is None or isinstance(v, scalar)}
    engine = record.get("engine")
    if isinstance(engine, dict):
        for key, value in engine.items():
            if key not in row and (value is None or isinstance(value, scalar)):
                row[key] = value
    if machine is not None:
        row["machine"] = machine
    elif isinstance(engine, dict) or "machine" in row or "L1" in row:  # a record of an engine: its own, or flat (optimize's, complete's)
        row["machine"] = row.get("machine") or "hinged"  # an engine that names none is the paper's hinged one
    row["warnings"] = "; ".join(record.get("warnings") or [])
    row["error"] = record.get("error", "")
    return row


def to_frame(answer):
    """A pandas DataFrame of a result (pandas, Debian's python3-pandas, is imported here only):
    a Monte Carlo run's draws, a row a sample, its drawn inputs and R, T, eps, v and failure; a
    shot's series frames (shot(..., series=True)), a row a moment; a sweep, a row a point, the
    value varied first; a list of records (the optima of optimize, compare's machines, shots of a
    batch) or contest(machine="all")'s dict of machines, a row each; or one record, one row. Each
    record's row has its numbers and texts, its engine's inputs and machine, and its warnings and
    error."""
    import pandas as pd

    if isinstance(answer, list):
        return pd.DataFrame([_frame_row(r) for r in answer])
    if isinstance(answer, dict) and "points" in answer and "vary" in answer:  # a sweep: a row a point, the value varied first
        # A failed point holds the value varied under its key, as the sweep's text gave it: the
        # column takes the sweep's number instead, and the point keeps its error.
        frame = to_frame([{k: v for k, v in p.items() if k != answer["vary"]} for p in answer["points"]])
        frame = frame.drop(columns=[answer["vary"]], errors="ignore")  # the engine's value, which the sweep's number replaces
        frame.insert(0, answer["vary"], answer["values"])
        return frame
    if isinstance(answer, dict) and "draws" in answer:
        return pd.DataFrame(answer["draws"])
    if isinstance(answer, dict) and "series" in answer:
        return pd.DataFrame(answer["series"]["frames"])
    if isinstance(answer, dict) and answer and all(isinstance(v, (dict, TrebuchetError)) for v in answer.values()) \
            and all(isinstance(v, TrebuchetError) or "engine" in v for v in answer.values()):  # contest(machine="all")
        return pd.DataFrame([_frame_row(record, machine) for machine, record in answer.items()])
    if isinstance(answer, dict):
        return pd.DataFrame([_frame_row(answer)])
    raise TypeError("to_frame takes a Monte Carlo run, a shot with its series, a sweep, a record, contest's machines, or a list of records")
