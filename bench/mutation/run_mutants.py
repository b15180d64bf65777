#!/usr/bin/env python3
"""Mutation benchmark for mergeguard's fuzzer.

Copies the tracked source tree (git ls-files, working-tree contents) to a work directory, builds
it once unmutated, then for every mutant of bench/mutation/mutants.json: applies it (its `find`
text must occur exactly once), rebuilds, compares a fixed-seed campaign summary with the
unmutated one (same summary = equivalent), runs time-boxed campaigns on several seeds with
`--search random` and `--search guided`, runs the CTest suite, and restores the file. Prints a
row per mutant and a Markdown table at the end (bench/mutation/README.md explains the columns).

Standard library only. Example (the full benchmark):
    python3 bench/mutation/run_mutants.py --seeds 10 --time 60 --out bench/mutation/results.md
"""

from __future__ import annotations

import argparse
import concurrent.futures
import fcntl
import io
import json
import math
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tarfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
MODES = ("random", "guided")
PLANNERS = ("rcpp", "rcpp-coop")
KINDS = ("planner", "simulator", "rule")
# Keys of the campaign summary that depend on the clock or on how the campaign was run, not on
# what it found: dropped (at any depth) before two fixed-seed summaries are compared.
VOLATILE_KEYS = {
    "seconds", "scenarios_per_second", "date", "time_budget_s", "first_failure_s", "first_new_failure_s", "elapsed_s",
    "remaining_s", "timeline", "jobs", "corpus", "shrink_seconds",
}
CTEST_ENV = {"RC_PARAMS": "max_success=100 seed=20261123"}
TARGET_FRACTION = 0.9  # caught on at least 9 of 10 seeds
TARGET_SPEEDUP = 2.0   # guided reaches the first failure at least twice as fast as random (median)
# A mutant is rare when a random campaign fails on fewer than RARE_RATE of its scenarios (its
# `random_rate` in mutants.json, measured with `mergeguard fuzz --runs N`); on every rare mutant
# guided search should reach the first failure at least RARE_TARGET_SPEEDUP times sooner (median
# over the seeds, a campaign that misses counting as never).
RARE_RATE = 1e-4
RARE_TARGET_SPEEDUP = 3.0

_children_lock = threading.Lock()
_children: set[subprocess.Popen] = set()
_stopping = threading.Event()


def log(msg: str) -> None:
    print(time.strftime("%H:%M:%S"), msg, flush=True)


def run(cmd: list[str], *, cwd: Path | None = None, env: dict | None = None, timeout: float | None = None,
        log_path: Path | None = None) -> tuple[int | None, str, str]:
    """Runs cmd; returns (exit code or None on time-out, stdout, stderr). Children are tracked so
    that an interrupted benchmark kills them (by process id, nothing else)."""
    full_env = dict(os.environ)
    if env:
        full_env.update(env)
    if _stopping.is_set():
        raise KeyboardInterrupt
    proc = subprocess.Popen(cmd, cwd=cwd, env=full_env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    with _children_lock:
        _children.add(proc)
    try:
        out, err = proc.communicate(timeout=timeout)
        code: int | None = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        code = None
    finally:
        with _children_lock:
            _children.discard(proc)
    if log_path is not None:
        log_path.parent.mkdir(parents=True, exist_ok=True)
        log_path.write_text("$ " + " ".join(cmd) + "\n" + out + ("\n--- stderr ---\n" + err if err else ""))
    return code, out, err


def kill_children() -> None:
    _stopping.set()
    with _children_lock:
        for proc in list(_children):
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def _raise_interrupt(signum, frame):
    raise KeyboardInterrupt


def tail(text: str, lines: int = 6) -> str:
    return "\n".join(text.strip().splitlines()[-lines:])


# ---------------------------------------------------------------- mutants


def load_mutants(path: Path, repo: Path) -> list[dict]:
    mutants = json.loads(path.read_text())
    if not isinstance(mutants, list):
        raise SystemExit(f"{path}: expected a JSON list of mutants")
    seen = set()
    for k, m in enumerate(mutants):
        where = f"{path}: mutant {k} ({m.get('id', '?')})"
        for key in ("id", "file", "find", "replace", "planner", "kind", "what"):
            if not isinstance(m.get(key), str) or (key != "replace" and not m[key]):
                raise SystemExit(f"{where}: '{key}' must be a non-empty string")
        if m["id"] in seen:
            raise SystemExit(f"{where}: duplicate id")
        seen.add(m["id"])
        if m["planner"] not in PLANNERS:
            raise SystemExit(f"{where}: planner must be one of {PLANNERS}")
        if m["kind"] not in KINDS:
            raise SystemExit(f"{where}: kind must be one of {KINDS}")
        if m["find"] == m["replace"]:
            raise SystemExit(f"{where}: find and replace are the same")
        if not (repo / m["file"]).is_file():
            raise SystemExit(f"{where}: no file {m['file']}")
        rate = m.get("random_rate")
        if rate is not None and not (isinstance(rate, dict) and all(isinstance(rate.get(k), int) for k in
                                                                   ("failing", "runs", "seed")) and rate["runs"] > 0):
            raise SystemExit(f"{where}: 'random_rate' must be {{\"failing\": int, \"runs\": int > 0, \"seed\": int}}")
    return mutants


def is_rare(m: dict) -> bool:
    rate = m.get("random_rate")
    return rate is not None and rate["failing"] < RARE_RATE * rate["runs"]


def occurrences(text: str, find: str) -> int:
    return text.count(find)


class Mutation:
    """Applies one mutant to the work copy; restores the file on exit, whatever happens."""

    def __init__(self, src: Path, mutant: dict):
        self.path = src / mutant["file"]
        self.mutant = mutant
        self.original: str | None = None

    def __enter__(self) -> "Mutation":
        text = self.path.read_text()
        n = occurrences(text, self.mutant["find"])
        if n != 1:
            raise ValueError(f"mutant {self.mutant['id']}: 'find' occurs {n} times in {self.mutant['file']} (must be once)")
        self.original = text
        self.path.write_text(text.replace(self.mutant["find"], self.mutant["replace"], 1))
        return self

    def __exit__(self, *exc) -> None:
        if self.original is not None:
            # A second Ctrl-C or a SIGTERM must not cut the restore short.
            blocked = {signal.SIGINT, signal.SIGTERM, signal.SIGHUP}
            old = signal.pthread_sigmask(signal.SIG_BLOCK, blocked)
            try:
                self.path.write_text(self.original)  # new mtime: make rebuilds it
            finally:
                signal.pthread_sigmask(signal.SIG_SETMASK, old)


# ---------------------------------------------------------------- tree, build


def tracked_files(repo: Path, rev: str | None):
    """(relative path, contents, executable) of every tracked file: the working-tree contents of
    `git ls-files`, or the tree of commit `rev`."""
    if rev is None:
        code, out, err = run(["git", "-C", str(repo), "ls-files", "-z"])
        if code != 0:
            raise SystemExit(f"git ls-files failed in {repo}: {err.strip()}")
        for rel in filter(None, out.split("\0")):
            src = repo / rel
            if src.is_file():  # not deleted in the working tree
                yield rel, src.read_bytes(), os.access(src, os.X_OK)
        return
    proc = subprocess.run(["git", "-C", str(repo), "archive", "--format=tar", rev], capture_output=True)
    if proc.returncode != 0:
        raise SystemExit(f"git archive {rev} failed: {proc.stderr.decode().strip()}")
    with tarfile.open(fileobj=io.BytesIO(proc.stdout)) as tar:
        for member in tar.getmembers():
            if member.isfile():
                yield member.name, tar.extractfile(member).read(), bool(member.mode & 0o111)


def sync_tree(repo: Path, dest: Path, rev: str | None) -> int:
    """Copies the tracked files to dest; only files whose contents differ are written, so that
    the build in the work directory stays incremental."""
    written = 0
    for rel, data, executable in tracked_files(repo, rev):
        dst = dest / rel
        if dst.is_file() and dst.read_bytes() == data:
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        dst.write_bytes(data)
        dst.chmod(0o755 if executable else 0o644)
        written += 1
    return written


def configure(src: Path, build: Path, logs: Path) -> None:
    code, out, err = run(["cmake", "-S", str(src), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"],
                         log_path=logs / "configure.log")
    if code != 0:
        raise SystemExit(f"cmake configure failed (see {logs / 'configure.log'}):\n{tail(out + err, 20)}")


def build(build_dir: Path, jobs: int, target: str | None, log_path: Path) -> tuple[bool, str]:
    cmd = ["cmake", "--build", str(build_dir), "-j", str(jobs)]
    if target:
        cmd += ["--target", target]
    code, out, err = run(cmd, log_path=log_path)
    if code == 0:
        return True, ""
    errors = [line for line in (out + "\n" + err).splitlines() if "error" in line.lower()]
    return False, "\n".join(errors[:5]) or tail(out + err)


# ---------------------------------------------------------------- campaigns


def normalise(doc):
    if isinstance(doc, dict):
        return {k: normalise(v) for k, v in doc.items() if k not in VOLATILE_KEYS}
    if isinstance(doc, list):
        return [normalise(v) for v in doc]
    return doc


def signature_records(summary: dict) -> list[dict]:
    """The summary's per-signature records (a list under 'signatures' or 'signature_list')."""
    for key in ("signatures", "signature_list"):
        if isinstance(summary.get(key), list):
            return summary[key]
    return []


def runs_command(exe: Path, planner: str, runs: int, seed: int, corpus: str = "") -> list[str]:
    """`mergeguard fuzz --runs N --seed S --jobs 2 --json` of a planner: a campaign of fixed runs,
    its summary the same whatever the machine's load."""
    return [str(exe), "fuzz", "--runs", str(runs), "--seed", str(seed), "--planner", planner, "--corpus", corpus,
            "--jobs", "2", "--json"]


def fixed_summary(exe: Path, planner: str, runs: int, logs: Path, tag: str) -> dict:
    cmd = runs_command(exe, planner, runs, 1)
    t0 = time.monotonic()
    r, doc = fuzz_summary(cmd, logs / f"fixed-{tag}-{planner}.log", max(600.0, runs * 0.5))
    r["wall_s"] = round(time.monotonic() - t0, 1)
    if doc is None:
        return r
    r["summary"] = normalise(doc)
    r["violations"] = doc.get("violations")
    r["signatures"] = sorted(s.get("signature", "?") for s in signature_records(doc))
    return r


def rate_campaign(exe: Path, planner: str, runs: int, seed: int, logs: Path, tag: str) -> dict:
    """How often random search fails: a `fuzz --runs N --seed S --jobs 2` of the build, with the
    scenarios of each signature ({"runs", "seed", "signatures": {signature: scenarios}})."""
    r, doc = fuzz_summary(runs_command(exe, planner, runs, seed), logs / f"rate-{tag}-{planner}.log",
                          max(600.0, runs * 0.5))
    r.update({"runs": runs, "seed": seed})
    if doc is not None:
        r["signatures"] = {s.get("signature", "?"): s.get("scenarios", 0) for s in signature_records(doc)}
    return r


def measured_rate(base: dict, mutant: dict) -> dict:
    """The mutant's random rate against the unmutated build's same campaign: its signatures the
    unmutated build does not have, and `failing`, the most scenarios of one of them (a lower bound
    of the failing scenarios: one scenario fails several properties)."""
    if "error" in mutant or "error" in base:
        return {"runs": mutant["runs"], "seed": mutant["seed"], "error": mutant.get("error") or base.get("error")}
    new = {k: v for k, v in mutant.get("signatures", {}).items() if k not in base.get("signatures", {})}
    return {"runs": mutant["runs"], "seed": mutant["seed"], "new_signatures": new, "failing": max(new.values(), default=0)}


def fuzz_summary(cmd: list[str], log_path: Path, timeout: float) -> tuple[dict, dict | None]:
    """Runs a `mergeguard fuzz ... --json`: ({"exit": code} or with an "error"), and its summary
    (None when it crashed, timed out or printed no JSON)."""
    code, out, err = run(cmd, log_path=log_path, timeout=timeout)
    r: dict = {"exit": code}
    if code not in (0, 1):
        r["error"] = "timed out" if code is None else f"exit {code}: {tail(err, 3)}"
        return r, None
    try:
        return r, json.loads(out)
    except json.JSONDecodeError as e:
        r["error"] = f"unreadable JSON summary: {e}"
        return r, None


def summary_difference(base: dict, mutant: dict) -> list[str]:
    """What differs between two fixed-seed summaries: the failing-scenario count, the
    signatures, the rules whose margins moved, other top-level keys."""
    a, b = base.get("summary", {}), mutant.get("summary", {})
    keys = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
    out = []
    if "violations" in keys:
        out.append(f"violations {a.get('violations')} -> {b.get('violations')}")
    if a.get("signature_list", a.get("signatures")) != b.get("signature_list", b.get("signatures")):
        new = sorted(set(mutant.get("signatures", [])) - set(base.get("signatures", [])))
        if new:
            out.append("new signatures " + ", ".join(new))
    if "margins" in keys:
        ma, mb = a.get("margins", {}), b.get("margins", {})
        rules = sorted(r for r in set(ma) | set(mb) if ma.get(r) != mb.get(r))
        out.append(f"margins of {len(rules)} rule(s)" + (": " + ", ".join(rules) if len(rules) <= 4 else ""))
    skip = {"violations", "margins", "signatures", "signature_list", "property_failures", "failures_by_property",
            "failures_by_rule", "failures_by_party"}
    out += [k for k in keys if k not in skip]
    return out


def known_corpus(exe: Path, planner: str, runs: int, seed: int, dest: Path, logs: Path) -> dict:
    """The unmutated build's known failures: a `fuzz --runs N --seed S --jobs 2` whose cases (one per
    signature) go into `dest`. The campaigns start from a copy of it and stop at the first failure
    with another signature (`--stop-on-new-failure`): the planner's open findings, which a campaign
    meets every few tens of seconds, no longer end a campaign before a rare mutant shows."""
    if dest.exists():
        shutil.rmtree(dest)
    dest.mkdir(parents=True)
    r, doc = fuzz_summary(runs_command(exe, planner, runs, seed, str(dest)), logs / f"known-{planner}.log",
                          max(900.0, runs * 0.5))
    if doc is not None:
        r["signatures"] = sorted(s.get("signature", "?") for s in signature_records(doc))
    return r


def campaign(exe: Path, planner: str, seed: int, mode: str, time_s: float, corpus: Path, log_path: Path,
             known: Path | None = None) -> dict:
    if corpus.exists():
        shutil.rmtree(corpus)
    if known is not None:
        shutil.copytree(known, corpus)
    else:
        corpus.mkdir(parents=True)
    cmd = [str(exe), "fuzz", "--time", str(time_s), "--seed", str(seed), "--planner", planner, "--jobs", "1",
           "--search", mode, "--stop-on-new-failure" if known is not None else "--stop-on-failure",
           "--corpus", str(corpus), "--json"]
    # A failure found just before the deadline is still shrunk (up to 60 s + its grace period).
    outcome, doc = fuzz_summary(cmd, log_path, time_s + 300.0)
    r: dict = {"seed": seed, "mode": mode, **outcome}
    if doc is None:
        return r
    r["scenarios"] = doc.get("scenarios")
    r["seconds"] = doc.get("seconds")
    if known is not None:  # caught: a failure the known corpus has no signature of
        r["caught"] = doc.get("first_new_failure_run") is not None
        r["first_failure_s"] = doc.get("first_new_failure_s")
        r["first_failure_run"] = doc.get("first_new_failure_run")
    else:
        r["caught"] = r["exit"] == 1
        r["first_failure_s"] = doc.get("first_failure_s")
        r["first_failure_run"] = doc.get("first_failure_run")
    sigs = [s for s in signature_records(doc) if not (known is not None and s.get("known_before"))]
    r["signatures"] = sorted(s.get("signature", "?") for s in sigs)
    vehicles = [s["case_vehicles"] for s in sigs if s.get("case") and isinstance(s.get("case_vehicles"), int)]
    r["case_vehicles"] = min(vehicles) if vehicles else None
    shutil.rmtree(corpus, ignore_errors=True)
    return r


def run_campaigns(exe: Path, planner: str, seeds: int, modes: list[str], time_s: float, parallel: int, work: Path,
                  logs: Path, tag: str, known: Path | None = None) -> list[dict]:
    jobs = [(seed, mode) for seed in range(1, seeds + 1) for mode in modes]
    results: list[dict] = []
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=max(1, parallel))
    try:
        futures = [pool.submit(campaign, exe, planner, seed, mode, time_s, work / "corpora" / tag / f"{mode}-{seed}",
                               logs / f"campaign-{mode}-{seed}.log", known) for seed, mode in jobs]
        for f in concurrent.futures.as_completed(futures):
            results.append(f.result())
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        kill_children()
        raise
    pool.shutdown()
    results.sort(key=lambda r: (MODES.index(r["mode"]) if r["mode"] in MODES else 9, r["seed"]))
    return results


def attribute(campaigns: list[dict], baseline: list[dict] | None) -> None:
    """Marks the catches the unmutated build would have made as well (the open findings of
    rcpp-coop, for instance), which are not credited to the mutant: the unmutated campaign of the
    same planner, seed and mode failed at a run index no later than the mutant's first failing
    run, and every signature of the mutant's failure is one the unmutated campaigns of that
    planner also found. A failure with a signature the unmutated build never showed is the
    mutant's, whenever it comes."""
    base = {(b["seed"], b["mode"]): b for b in baseline or []}
    base_signatures = {sig for b in baseline or [] for sig in b.get("signatures", [])}
    for r in campaigns:
        b = base.get((r["seed"], r["mode"]))
        r["also_unmutated"] = bool(r.get("caught") and b and b.get("caught") and
                                   isinstance(b.get("first_failure_run"), int) and
                                   isinstance(r.get("first_failure_run"), int) and
                                   r["first_failure_run"] >= b["first_failure_run"] and
                                   set(r.get("signatures", [])) <= base_signatures)


def credited(r: dict) -> bool:
    return bool(r.get("caught")) and not r.get("also_unmutated")


def mode_stats(campaigns: list[dict], mode: str) -> dict:
    rs = [r for r in campaigns if r["mode"] == mode]
    caught = [r for r in rs if credited(r)]
    times = [r["first_failure_s"] for r in caught if isinstance(r.get("first_failure_s"), (int, float))]
    runs = [r["first_failure_run"] for r in caught if isinstance(r.get("first_failure_run"), int)]
    # Over every seed that ran without error, a miss counting as never (infinity): the median a rare
    # mutant is judged by. None (JSON null) when more than half the seeds missed.
    all_times = times + [math.inf] * sum(1 for r in rs if not credited(r) and "error" not in r)
    censored = statistics.median(all_times) if all_times else math.inf
    return {
        "median_first_failure_all_seeds_s": None if math.isinf(censored) else censored,
        "seeds": len(rs),
        "caught": len(caught),  # credited to the mutant
        "also_unmutated": sum(1 for r in rs if r.get("also_unmutated")),
        "errors": [f"seed {r['seed']}: {r['error']}" for r in rs if "error" in r],
        "median_first_failure_s": statistics.median(times) if times else None,
        "median_first_failure_run": statistics.median(runs) if runs else None,
        "signatures": sorted({s for r in caught for s in r.get("signatures", [])}),
    }


# ---------------------------------------------------------------- ctest


def run_ctest(build_dir: Path, jobs: int, log_path: Path, exclude: str = "") -> dict:
    cmd = ["ctest", "--test-dir", str(build_dir), "-j", str(jobs), "--timeout", "600", "--stop-on-failure"]
    if exclude:
        cmd += ["-E", exclude]
    t0 = time.monotonic()
    code, out, err = run(cmd, env=CTEST_ENV, log_path=log_path, timeout=3600.0)
    r = {"exit": code, "wall_s": round(time.monotonic() - t0, 1), "caught": code != 0}
    failed = []
    for line in out.splitlines():
        # "  7/351 Test  #12: rss_distance_monitor.Something ..........***Failed    0.05 sec"
        if "***" in line and "Test" in line and ":" in line:
            name = line.split(":", 1)[1].split("***", 1)[0].strip().rstrip(".").strip()
            failed.append(name)
    if code is None:
        r["error"] = "ctest timed out"
    r["failed"] = failed
    r["first_failed"] = failed[0] if failed else (None if code == 0 else tail(out + err, 2))
    summary = [line for line in out.splitlines() if "tests passed" in line]
    r["summary"] = summary[-1].strip() if summary else None
    return r


# ---------------------------------------------------------------- report


def fmt_time(t) -> str:
    return "-" if t is None else f"{t:.1f}"


def md_escape(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def mutant_status(r: dict, seeds: int) -> str:
    """Why a mutant could not be measured at all ('' when it was)."""
    if r.get("apply_error"):
        return "does not apply"
    if r.get("compile_error") is not None:
        return "does not compile"
    return ""


def vehicles_median(r: dict):
    v = [c["case_vehicles"] for c in r.get("campaigns", []) if credited(c) and c.get("case_vehicles") is not None]
    return statistics.median(v) if v else None


def needed(seeds: int) -> int:
    return math.ceil(TARGET_FRACTION * seeds - 1e-9)


def rare_speedups(results: list[dict], seeds: int) -> list[dict]:
    """Per rare mutant: random's and guided's median time to the first failure over all seeds (a
    miss counting as never) and their ratio; `met` whether guided is RARE_TARGET_SPEEDUP times
    faster. A median that is never (more than half the seeds missed) is None; random never and
    guided timed meets the target, guided never does not."""
    out = []
    for r in results:
        if r.get("baseline") or mutant_status(r, seeds) or not r.get("rare"):
            continue
        st = r.get("modes", {})
        if "random" not in st or "guided" not in st:
            continue
        rnd = st["random"].get("median_first_failure_all_seeds_s")
        gd = st["guided"].get("median_first_failure_all_seeds_s")
        if gd is None:
            ratio, met = None, False
        elif rnd is None:
            ratio, met = None, True
        else:
            ratio = rnd / gd if gd > 0 else math.inf
            met = ratio >= RARE_TARGET_SPEEDUP
        out.append({"id": r["id"], "random_s": rnd, "guided_s": gd, "speedup": None if ratio is None or math.isinf(ratio)
                    else ratio, "met": met})
    return out


def aggregate(results: list[dict], seeds: int, modes: list[str]) -> dict:
    ratios, run_ratios, excluded = [], [], []
    gaps, short = [], []
    for r in results:
        if r.get("baseline") or mutant_status(r, seeds):
            continue
        st = r.get("modes", {})
        rnd, gd = st.get("random"), st.get("guided")
        if rnd and gd and rnd["caught"] > 0:
            if rnd["median_first_failure_s"] and gd["median_first_failure_s"]:
                ratios.append((r["id"], rnd["median_first_failure_s"] / gd["median_first_failure_s"]))
                if rnd.get("median_first_failure_run") is not None and gd.get("median_first_failure_run") is not None:
                    # run indices from 0: +1 so that a failure in the very first run counts as one run
                    run_ratios.append((r["id"], (rnd["median_first_failure_run"] + 1) / (gd["median_first_failure_run"] + 1)))
            else:
                excluded.append(r["id"])
        if seeds > 0 and r.get("differs"):
            best = max((st[m]["caught"] for m in modes if m in st), default=0)
            if best < needed(seeds):
                gaps.append(r["id"])
            for m in modes:
                if m in st and st[m]["caught"] < needed(seeds):
                    short.append((r["id"], m))
    out = {"speedups": ratios, "run_speedups": run_ratios, "speedup_excluded": excluded, "gaps": gaps,
           "below_target": short, "rare": rare_speedups(results, seeds)}
    out["median_speedup"] = statistics.median(v for _, v in ratios) if ratios else None
    out["median_run_speedup"] = statistics.median(v for _, v in run_ratios) if run_ratios else None
    return out


def markdown(results: list[dict], args, agg: dict, header: dict) -> str:
    seeds, modes = args.seeds, args.modes
    lines = [
        "# Mutation benchmark of the fuzzer",
        "",
        f"{header['date']}, source {header['source']}; {seeds} seed(s) x {len(modes)} search mode(s) x {args.time:g} s "
        f"per campaign (`--jobs 1 "
        + (f"--stop-on-new-failure` against the unmutated build's failures in {getattr(args, 'known_runs', 0):,} runs "
           f"of seed {getattr(args, 'known_seed', 0)}" if getattr(args, "known_runs", 0) > 0 else "--stop-on-failure`")
        + f", {args.parallel} at a time); fixed-seed summaries "
        f"`--runs {args.fixed_runs} --seed 1 --jobs 2`; CTest with RC_PARAMS=\"{CTEST_ENV['RC_PARAMS']}\""
        + (" (not run)" if args.no_ctest else "") + (f", without the tests matching `{args.ctest_exclude}`"
                                                     if args.ctest_exclude and not args.no_ctest else "")
        + f". Wall time {header.get('wall', '?')}.",
        "",
    ]
    cols = ["id", "kind", "planner", "what", "fixed-seed summary differs"]
    for m in modes:
        cols += [f"{m}: caught", f"{m}: median t1 (s)"]
    cols += ["median vehicles in minimal case", "ctest"]
    lines.append("| " + " | ".join(cols) + " |")
    lines.append("|" + "---|" * len(cols))
    for r in results:
        status = mutant_status(r, seeds)
        row = [r["id"], r.get("kind", "-"), r.get("planner", "-"), md_escape(r.get("what", ""))]
        if status:
            detail = r.get("apply_error") or r.get("compile_error") or ""
            row.append(f"**{status}**: {md_escape(str(detail))[:200]}")
            row += ["-"] * (len(cols) - len(row))
            lines.append("| " + " | ".join(row) + " |")
            continue
        if r.get("baseline"):
            row.append("(reference)")
        else:
            diff = r.get("difference") or []
            row.append(("yes: " + md_escape("; ".join(diff))[:200]) if r.get("differs") else "no (equivalent)")
        st = r.get("modes", {})
        for m in modes:
            if m in st:
                s = st[m]
                cell = f"{s['caught']}/{s['seeds']}"
                if s.get("also_unmutated"):
                    cell += f" (+{s['also_unmutated']} as unmutated)"
                if s["errors"]:
                    cell += f" ({len(s['errors'])} errors)"
                row += [cell, fmt_time(s["median_first_failure_s"])]
            else:
                row += ["-", "-"]
        vm = vehicles_median(r)
        row.append("-" if vm is None else f"{vm:g}")
        ct = r.get("ctest")
        if not ct:
            row.append("-")
        elif ct.get("build_error"):
            row.append("tests do not compile")
        elif ct.get("caught"):
            row.append("caught: " + md_escape(str(ct.get("first_failed") or "?"))[:80])
        else:
            row.append("not caught")
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "## Aggregate", ""]
    if agg["median_speedup"] is not None:
        ok = agg["median_speedup"] >= TARGET_SPEEDUP
        lines.append(f"- Median over the {len(agg['speedups'])} mutant(s) that random search catches of "
                     f"(random median time to the first failure / guided median time): "
                     f"**{agg['median_speedup']:.2f}** (target >= {TARGET_SPEEDUP:g}: {'met' if ok else 'not met'}); "
                     + ", ".join(f"{i} {v:.2f}" for i, v in agg["speedups"]) + ".")
        if agg.get("median_run_speedup") is not None:
            lines.append(f"- The same in runs (median index of the first failing run, +1; independent of the machine's "
                         f"load): **{agg['median_run_speedup']:.2f}**; "
                         + ", ".join(f"{i} {v:.2f}" for i, v in agg["run_speedups"]) + ".")
    else:
        lines.append("- No speed-up figure: random search caught no mutant with both modes timed.")
    rated = [r for r in results if r.get("measured_rate") and "error" not in r["measured_rate"]]
    if rated:
        lines.append("- Random rates measured by this run (`--rate-runs`; failing scenarios with a signature the "
                     "unmutated build's same campaign lacks): "
                     + "; ".join(f"{r['id']} {r['measured_rate']['failing']} in {r['measured_rate']['runs']:,} "
                                 f"(seed {r['measured_rate']['seed']}, {'rare' if r.get('rare') else 'not rare'})"
                                 for r in rated) + ".")
    if agg.get("rare"):
        def cell(t):
            return f"{t:.1f} s" if t is not None else f"never (> {args.time:g} s on most seeds)"

        def ratio(x):
            if x["speedup"] is not None:
                return f"{x['speedup']:.2f}"
            return "guided only" if x["met"] else "-"
        every = all(x["met"] for x in agg["rare"])
        lines.append(f"- **Rare mutants** (a random campaign fails on fewer than 1 in {1 / RARE_RATE:,.0f} scenarios; "
                     f"median over all seeds, a miss counting as never): guided at least {RARE_TARGET_SPEEDUP:g} times "
                     f"faster on every one: **{'met' if every else 'not met'}**; "
                     + "; ".join(f"{x['id']} random {cell(x['random_s'])}, guided {cell(x['guided_s'])}, "
                                 f"speed-up {ratio(x)}" for x in agg["rare"]) + ".")
    if agg["speedup_excluded"]:
        lines.append("- Left out of the speed-up (random caught it, guided never did or gave no time): "
                     + ", ".join(agg["speedup_excluded"]) + ".")
    if seeds > 0:
        by_id = {r["id"]: r for r in results}

        def ctest_note(i: str) -> str:
            ct = by_id[i].get("ctest")
            if not ct:
                return i
            return f"{i} (CTest {'catches' if ct.get('caught') and not ct.get('build_error') else 'misses'} it)"

        lines.append(f"- Target: every mutant whose fixed-seed summary differs is caught on at least {needed(seeds)} "
                     f"of {seeds} seeds. **Gaps** (not met by any search mode): "
                     + (", ".join(ctest_note(i) for i in agg["gaps"]) if agg["gaps"] else "none") + ".")
        if agg["below_target"]:
            lines.append("- Below the target per mode: "
                         + ", ".join(f"{i} ({m})" for i, m in agg["below_target"]) + ".")
    def eq_note(r: dict) -> str:
        notes = []
        if any(st["caught"] for st in r.get("modes", {}).values()):
            notes.append("yet a campaign caught it: not truly equivalent")
        ct = r.get("ctest")
        if ct and ct.get("caught"):
            notes.append(f"CTest catches it: {ct.get('first_failed')}")
        return r["id"] + (f" ({'; '.join(notes)})" if notes else "")

    eq = [eq_note(r) for r in results if not r.get("baseline") and not mutant_status(r, seeds) and r.get("differs") is False]
    lines.append("- Equivalent (fixed-seed summary identical to the unmutated build's): " + (", ".join(eq) or "none") + ".")
    bad = [f"{r['id']} ({mutant_status(r, seeds)})" for r in results if mutant_status(r, seeds)]
    if bad:
        lines.append("- Not measured: " + ", ".join(bad) + ".")
    errs = [f"{r['id']}: {e}" for r in results for s in r.get("modes", {}).values() for e in s["errors"]]
    if errs:
        lines.append("- Campaign errors (exit code other than 0/1, or no summary): " + "; ".join(errs[:20]) + ".")
    base_ct = next((r.get("ctest") for r in results if r.get("baseline") and r.get("ctest")), None)
    if base_ct and base_ct.get("caught"):
        lines.append(f"- **The unmutated build already fails CTest** ({base_ct.get('first_failed')}): the ctest column "
                     "is not meaningful.")
    found = [(r["id"], sorted({s for st in r.get("modes", {}).values() for s in st["signatures"]})) for r in results]
    found = [(i, sigs) for i, sigs in found if sigs]
    if found:
        lines += ["", "## Signatures of the credited catches (for the unmutated rows: what they found)", ""]
        lines += [f"- {i}: " + ", ".join(f"`{s}`" for s in sigs) for i, sigs in found]
    return "\n".join(lines) + "\n"


def print_row(r: dict, seeds: int, modes: list[str]) -> None:
    status = mutant_status(r, seeds)
    if status:
        log(f"== {r['id']}: {status}: {r.get('apply_error') or r.get('compile_error')}")
        return
    parts = [f"== {r['id']}", "reference" if r.get("baseline") else f"differs={'yes' if r.get('differs') else 'no'}"]
    for m in modes:
        s = r.get("modes", {}).get(m)
        if s:
            parts.append(f"{m} {s['caught']}/{s['seeds']}"
                         + (f" (+{s['also_unmutated']} as unmutated)" if s.get("also_unmutated") else "")
                         + f" t1={fmt_time(s['median_first_failure_s'])}"
                         + (f" errors={len(s['errors'])}" if s["errors"] else ""))
    vm = vehicles_median(r)
    if vm is not None:
        parts.append(f"vehicles={vm:g}")
    ct = r.get("ctest")
    if ct:
        parts.append("ctest " + ("does not compile" if ct.get("build_error") else
                                 f"caught ({ct.get('first_failed')})" if ct.get("caught") else "not caught"))
    log("  ".join(parts))


def rerender(raw: Path, out_md: Path | None) -> int:
    """The table of an earlier run, from its raw JSON, with this script's accounting."""
    doc = json.loads(raw.read_text())
    stored = doc.get("args", {})
    args = argparse.Namespace(seeds=stored.get("seeds", 10), modes=stored.get("modes", list(MODES)),
                              time=stored.get("time", 60.0), parallel=stored.get("parallel", 2),
                              fixed_runs=stored.get("fixed_runs", 2000), no_ctest=stored.get("no_ctest", False),
                              ctest_exclude=stored.get("ctest_exclude", ""), known_runs=stored.get("known_runs", 0),
                              known_seed=stored.get("known_seed", 0))
    results = doc["results"]
    base = {r["planner"]: r["campaigns"] for r in results if r.get("baseline") and r.get("campaigns")}
    for r in results:
        if r.get("campaigns"):
            if not r.get("baseline"):
                attribute(r["campaigns"], base.get(r["planner"]))
            r["modes"] = {m: mode_stats(r["campaigns"], m) for m in args.modes}
    agg = aggregate(results, args.seeds, args.modes)
    text = markdown(results, args, agg, doc.get("header", {"date": "?", "source": "?"}))
    if out_md:
        out_md.write_text(text)
        doc["aggregate"] = agg
        out_md.with_suffix(".json").write_text(json.dumps(doc, indent=2) + "\n")
    else:
        print(text)
    return 0


# ---------------------------------------------------------------- main


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=10, help="campaign seeds 1..S per search mode (0: no campaigns)")
    ap.add_argument("--time", type=float, default=60.0, help="seconds per campaign (--time of mergeguard fuzz)")
    ap.add_argument("--fixed-runs", type=int, default=2000, help="runs of the fixed-seed summary (seed 1)")
    ap.add_argument("--rate-runs", type=int, default=0,
                    help="measure each mutant's random rate over this many runs (0: no; see 'Rare mutants')")
    ap.add_argument("--rate-seed", type=int, default=4242, help="seed of the rate campaigns")
    ap.add_argument("--known-runs", type=int, default=30000,
                    help="campaigns stop at the first failure the unmutated build does not show in this many runs "
                         "(0: at the first failure)")
    ap.add_argument("--known-seed", type=int, default=4242, help="seed of the known-failure run")
    ap.add_argument("--only", default="", help="comma-separated mutant ids (default: all)")
    ap.add_argument("--modes", default=",".join(MODES), help="search modes to run (default: random,guided)")
    ap.add_argument("--no-ctest", action="store_true", help="skip the CTest suite")
    ap.add_argument("--ctest-exclude", default="", metavar="REGEX",
                    help="leave these tests out (ctest -E), e.g. CorpusReplay to see what the unit tests alone catch")
    ap.add_argument("--no-baseline-campaigns", action="store_true",
                    help="skip the campaigns of the unmutated build (its false-alarm reference)")
    ap.add_argument("--baseline-planners", default=",".join(PLANNERS),
                    help="planners whose unmutated build gets reference campaigns (default: all used)")
    ap.add_argument("--work", default="/tmp/mg-mutation", help="work directory (source copy, build, logs)")
    ap.add_argument("--out", default="", help="write the Markdown table here, and the raw JSON beside it")
    ap.add_argument("--parallel", type=int, default=2, help="campaigns run at once (each --jobs 1)")
    ap.add_argument("--build-jobs", type=int, default=2, help="parallel compile jobs")
    ap.add_argument("--mutants", default=str(HERE / "mutants.json"), help="mutant list")
    ap.add_argument("--rev", default=None,
                    help="benchmark this commit's tree instead of the working tree (git ls-files contents)")
    ap.add_argument("--list", action="store_true", help="check that every mutant applies to the tree, list, exit")
    ap.add_argument("--from-json", default="", metavar="RAW.json",
                    help="build nothing, run nothing: redo the table of an earlier run's raw results (to --out, or stdout)")
    args = ap.parse_args()
    signal.signal(signal.SIGTERM, _raise_interrupt)
    signal.signal(signal.SIGHUP, _raise_interrupt)
    args.modes = [m for m in args.modes.split(",") if m]
    if any(m not in MODES for m in args.modes):
        ap.error(f"--modes: each of {MODES}")
    if args.seeds < 0 or args.time <= 0 or args.fixed_runs < 1 or args.parallel < 1:
        ap.error("--seeds >= 0, --time > 0, --fixed-runs >= 1, --parallel >= 1")

    if args.from_json:
        return rerender(Path(args.from_json), Path(args.out).resolve() if args.out else None)

    code, out, _ = run(["git", "-C", str(HERE), "rev-parse", "--show-toplevel"])
    if code != 0:
        raise SystemExit(f"{HERE} is not inside a git repository")
    repo = Path(out.strip())
    mutants = load_mutants(Path(args.mutants), repo)
    if args.only:
        wanted = [i.strip() for i in args.only.split(",") if i.strip()]
        unknown = set(wanted) - {m["id"] for m in mutants}
        if unknown:
            raise SystemExit(f"--only: unknown mutant id(s) {', '.join(sorted(unknown))}")
        mutants = [m for m in mutants if m["id"] in wanted]

    if args.list:
        bad = 0
        for m in mutants:
            n = occurrences((repo / m["file"]).read_text(), m["find"])
            bad += n != 1
            print(f"{m['id']:32} {m['kind']:9} {m['planner']:9} {m['file']:36} {'ok' if n == 1 else f'FIND OCCURS {n} TIMES'}")
        return 1 if bad else 0

    work = Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    lock = open(work / ".lock", "w")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        raise SystemExit(f"another benchmark is running in {work}")
    src, build_dir, logs = work / "src", work / "build", work / "logs"
    exe = build_dir / "mergeguard"
    t_start = time.monotonic()
    code, head, _ = run(["git", "-C", str(repo), "rev-parse", "--short", args.rev or "HEAD"])
    if code != 0:
        raise SystemExit(f"unknown revision {args.rev}")
    dirty = "" if args.rev else run(["git", "-C", str(repo), "status", "--porcelain", "--untracked-files=no"])[1].strip()
    header = {"date": time.strftime("%Y-%m-%d %H:%M"), "source": head.strip() + (" + working-tree changes" if dirty else "")}

    out_md = Path(args.out).resolve() if args.out else None
    out_json = out_md.with_suffix(".json") if out_md else work / "results.json"
    results: list[dict] = []

    def save() -> None:
        agg = aggregate(results, args.seeds, args.modes)
        header["wall"] = f"{(time.monotonic() - t_start) / 60:.0f} min"
        doc = {"header": header, "args": {k: v for k, v in vars(args).items()}, "aggregate": agg, "results": results}
        out_json.write_text(json.dumps(doc, indent=2) + "\n")
        if out_md:
            out_md.write_text(markdown(results, args, agg, header))

    n_uncaught_worst = len(mutants) + (0 if args.no_baseline_campaigns else 2)
    worst_min = n_uncaught_worst * args.seeds * len(args.modes) * (args.time + 5) / args.parallel / 60
    log(f"{len(mutants)} mutant(s), {args.seeds} seed(s) x {len(args.modes)} mode(s) x {args.time:g} s; campaigns take at "
        f"most ~{worst_min:.0f} min (less for mutants caught early), plus builds and CTest")
    log(f"work directory {work}; results -> {out_json}" + (f" and {out_md}" if out_md else ""))

    try:
        written = sync_tree(repo, src, args.rev)
        log(f"source copy: {written} file(s) written to {src}")
        for m in mutants:  # fail loudly before hours of work
            n = occurrences((src / m["file"]).read_text(), m["find"])
            if n != 1:
                raise SystemExit(f"mutant {m['id']}: 'find' occurs {n} times in {m['file']} (must be exactly once)")
        configure(src, build_dir, logs)
        log("building the unmutated tree" + ("" if args.no_ctest else " (all targets, for CTest)"))
        ok, err = build(build_dir, args.build_jobs, None if not args.no_ctest else "mergeguard", logs / "build-base.log")
        if not ok:
            raise SystemExit(f"the unmutated tree does not build (see {logs / 'build-base.log'}):\n{err}")
        planners = sorted({m["planner"] for m in mutants})
        base_fixed = {}
        for p in planners:
            base_fixed[p] = fixed_summary(exe, p, args.fixed_runs, logs, "base")
            if "error" in base_fixed[p]:
                raise SystemExit(f"fixed-seed summary of the unmutated build ({p}): {base_fixed[p]['error']}")
            log(f"unmutated {p}: fixed-seed summary {base_fixed[p]['violations']} failing scenario(s) in "
                f"{args.fixed_runs} runs ({base_fixed[p]['wall_s']} s)")
        base_rate = {p: rate_campaign(exe, p, args.rate_runs, args.rate_seed, logs, "base")
                     for p in planners} if args.rate_runs > 0 else {}
        known: dict[str, Path] = {}
        if args.known_runs > 0 and args.seeds > 0:
            for p in planners:
                k = known_corpus(exe, p, args.known_runs, args.known_seed, work / "known" / p, logs)
                if "error" in k:
                    raise SystemExit(f"known-failure corpus of the unmutated build ({p}): {k['error']}")
                known[p] = work / "known" / p
                log(f"unmutated {p}: known failures in {args.known_runs} runs (seed {args.known_seed}): "
                    + (", ".join(k.get("signatures", [])) or "none"))
        base_ctest = None
        if not args.no_ctest:
            base_ctest = run_ctest(build_dir, args.build_jobs, logs / "ctest-base.log", args.ctest_exclude)
            log(f"unmutated CTest: {'FAILS: ' + str(base_ctest['first_failed']) if base_ctest['caught'] else 'passes'}"
                f" ({base_ctest['wall_s']} s)")
        base_campaigns: dict[str, list[dict]] = {}
        for p in planners:
            r = {"id": f"(unmutated, {p})", "baseline": True, "kind": "-", "planner": p,
                 "what": "the unmutated build: campaigns that fail here are false alarms or open findings",
                 "fixed": {k: v for k, v in base_fixed[p].items() if k != "summary"}}
            if p == planners[0] and base_ctest:
                r["ctest"] = base_ctest
            if args.seeds > 0 and not args.no_baseline_campaigns and p in args.baseline_planners.split(","):
                r["campaigns"] = run_campaigns(exe, p, args.seeds, args.modes, args.time, args.parallel, work,
                                               logs / f"base-{p}", f"base-{p}", known.get(p))
                base_campaigns[p] = r["campaigns"]
                r["modes"] = {m: mode_stats(r["campaigns"], m) for m in args.modes}
            results.append(r)
            print_row(r, args.seeds, args.modes)
            save()

        for m in mutants:
            r = {k: m[k] for k in ("id", "kind", "planner", "file", "what")}
            r["rare"] = is_rare(m)
            if m.get("random_rate") is not None:
                r["random_rate"] = m["random_rate"]
            results.append(r)
            t0 = time.monotonic()
            log(f"-- {m['id']} ({m['file']})")
            try:
                with Mutation(src, m):
                    ok, err = build(build_dir, args.build_jobs, "mergeguard", logs / m["id"] / "build.log")
                    if not ok:
                        r["compile_error"] = err
                        continue
                    r["fixed"] = fixed_summary(exe, m["planner"], args.fixed_runs, logs / m["id"], "mutant")
                    if "error" in r["fixed"]:  # the unmutated build ran it cleanly: behaviour differs
                        r["differs"] = True
                        r["difference"] = ["the fixed-seed campaign " + r["fixed"]["error"]]
                    else:
                        r["differs"] = r["fixed"]["summary"] != base_fixed[m["planner"]]["summary"]
                        r["difference"] = summary_difference(base_fixed[m["planner"]], r["fixed"])
                    r["fixed"].pop("summary", None)
                    if args.rate_runs > 0:
                        r["measured_rate"] = measured_rate(base_rate[m["planner"]], rate_campaign(
                            exe, m["planner"], args.rate_runs, args.rate_seed, logs / m["id"], "mutant"))
                        if "error" not in r["measured_rate"]:
                            r["rare"] = r["measured_rate"]["failing"] < RARE_RATE * args.rate_runs
                    if args.seeds > 0:
                        r["campaigns"] = run_campaigns(exe, m["planner"], args.seeds, args.modes, args.time,
                                                       args.parallel, work, logs / m["id"], m["id"],
                                                       known.get(m["planner"]))
                        attribute(r["campaigns"], base_campaigns.get(m["planner"]))
                        r["modes"] = {mode: mode_stats(r["campaigns"], mode) for mode in args.modes}
                    if not args.no_ctest:
                        ok, err = build(build_dir, args.build_jobs, None, logs / m["id"] / "build-all.log")
                        r["ctest"] = {"build_error": err, "caught": True} if not ok else run_ctest(
                            build_dir, args.build_jobs, logs / m["id"] / "ctest.log", args.ctest_exclude)
            except ValueError as e:
                r["apply_error"] = str(e)
            finally:
                r["wall_s"] = round(time.monotonic() - t0, 1)
                print_row(r, args.seeds, args.modes)
                save()
    except KeyboardInterrupt:
        kill_children()
        log("interrupted; the mutated file was restored; partial results saved")
        save()
        return 130
    save()
    # Leave the work build unmutated (the restored file is rebuilt on the next run anyway).
    agg = aggregate(results, args.seeds, args.modes)
    print()
    print(markdown(results, args, agg, header))
    return 0


if __name__ == "__main__":
    sys.exit(main())
