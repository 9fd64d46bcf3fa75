#!/usr/bin/env python3
"""Runs a subset of piglit on Pineda (or on Mesa's llvmpipe) and checks it against the
expectation lists in conformance/expectations/.

  conformance/run.py --group 'spec@!opengl 1.0' [--group ...] [--platform x11_egl]
                     [--driver pineda|llvmpipe] [--compare llvmpipe] [--html]
                     [--via library-path|vendor]

Results go to out/conformance/<driver>-<platform>/ (piglit's own results.json.bz2 and a
summary.txt). Exit status: 0 when every result is as expected, 1 on a regression or an
unexpected pass (both are listed), 2 on a usage or setup error.
"""
import argparse
import bz2
import json
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXPECTATIONS = os.path.join(ROOT, "conformance", "expectations")
PLATFORMS = ("x11_egl", "glx", "surfaceless_egl")
NOT_PASSING = ("fail", "crash", "timeout", "warn", "dmesg-fail", "dmesg-warn", "incomplete")


def ensure_installed():
    needed = [pkg for tool, pkg in (("piglit", "piglit"), ("xvfb-run", "xvfb")) if not shutil.which(tool)]
    if needed:
        print("installing: " + " ".join(needed), flush=True)
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        subprocess.run(["apt-get", "update", "-q"], check=True, env=env)
        subprocess.run(["apt-get", "install", "-y", "-q"] + needed, check=True, env=env)


def ensure_llvmpipe():
    if not os.path.exists("/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so"):
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        subprocess.run(["apt-get", "install", "-y", "-q", "libgl1-mesa-dri", "libegl-mesa0", "libglx-mesa0"],
                       check=True, env=env)


def driver_env(driver, platform, lib_dir, via="library-path"):
    env = dict(os.environ)
    env.pop("LD_LIBRARY_PATH", None)
    if driver == "pineda":
        if not os.path.exists(os.path.join(lib_dir, "libGL.so.1")):
            sys.exit(f"error: Pineda's libraries are not in {lib_dir}: build first (scripts/build.sh)")
        if via == "vendor":  # the system's libglvnd loads Pineda as its GLX and EGL vendor
            vendor_dir = os.path.join(os.path.abspath(lib_dir), "glvnd")
            env["LD_LIBRARY_PATH"] = vendor_dir  # holds only libGLX_pineda.so.0, libEGL_pineda.so.0
            env["__GLX_VENDOR_LIBRARY_NAME"] = "pineda"
            env["__EGL_VENDOR_LIBRARY_FILENAMES"] = os.path.join(vendor_dir, "50_pineda.json")
        else:
            env["LD_LIBRARY_PATH"] = os.path.abspath(lib_dir)  # piglit runs tests from another directory
        # piglit's fast skip asks wflinfo for a core-profile context to judge plain '#version 110/120'
        # parser tests; Pineda has no core profile, so it would skip tests that run (and pass) in
        # the compatibility context the test binary itself makes. Every test decides for itself.
        env["PIGLIT_NO_FAST_SKIP"] = "1"
    else:
        env.update(LIBGL_ALWAYS_SOFTWARE="1", GALLIUM_DRIVER="llvmpipe")
    if platform == "surfaceless_egl":
        env["PIGLIT_NO_WINDOW"] = "1"
    return env


def group_regex(groups):
    """A group is a prefix of test names: 'spec@!opengl 1.1', '...@texwrap 1d' or one whole test."""
    return ["^" + re.escape(g) for g in groups]


def load_results(results_dir, final=True):
    path = os.path.join(results_dir, "results.json.bz2")
    if final and os.path.exists(path):
        with bz2.open(path, "rt") as f:
            return json.load(f)["tests"]
    tests = {}  # an interrupted run: piglit keeps one file per finished test
    folder = os.path.join(results_dir, "tests")
    for name in os.listdir(folder) if os.path.isdir(folder) else []:
        try:
            with open(os.path.join(folder, name)) as f:
                tests.update(json.load(f))
        except (ValueError, OSError):
            pass
    return tests



def run_piglit(driver, platform, groups, args, lib_dir):
    via = f"-{args.via}" if driver == "pineda" and args.via != "library-path" else ""
    results_dir = os.path.join(ROOT, "out", "conformance", f"{driver}{via}-{platform}")
    shutil.rmtree(results_dir, ignore_errors=True)
    env = driver_env(driver, platform, lib_dir, args.via)
    cmd = ["piglit", "run", args.profile, "-p", platform, "-j", str(args.jobs), "-l", "dummy",
           "--timeout", str(args.timeout)]
    for r in group_regex(groups):
        cmd += ["-t", r]
    for x in args.exclude:
        cmd += ["-x", x]
    cmd.append(results_dir)
    if platform != "surfaceless_egl":
        # -noreset: without it Xvfb resets whenever its last client leaves, and a client that
        # connects during the reset gets "XOpenDisplay failed". With -j 2 and short tests that
        # happens several times a run, GL or not (plain Xlib programs hit it too).
        cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24 -noreset"] + cmd
    print(f"[{driver}] {' '.join(cmd)}", flush=True)
    start = time.time()
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    total = args.expected_total
    last_count, last_print = -1, 0.0
    while proc.poll() is None:
        time.sleep(2)
        done = load_results(results_dir, final=False)
        passes = sum(1 for t in done.values() if t["result"] == "pass")
        elapsed = time.time() - start
        eta = f", about {elapsed / len(done) * (total - len(done)):.0f}s left" if total and done else ""
        line = f"[{driver}] {len(done)}{'/' + str(total) if total else ''} done, {passes} pass, {elapsed:.0f}s{eta}"
        if len(done) != last_count or elapsed - last_print > 30:
            print(line, flush=True)
            last_count, last_print = len(done), elapsed
    output = proc.stdout.read()
    if proc.returncode != 0:
        print(output[-4000:])
        sys.exit(f"error: piglit exited with {proc.returncode}")
    elapsed = time.time() - start
    return load_results(results_dir), results_dir, elapsed


def whole_test_counts(tests, groups):
    counts = {}
    for g in groups:
        c = counts.setdefault(g, {})
        for name, t in tests.items():
            if name.startswith(g):
                c[t["result"]] = c.get(t["result"], 0) + 1
    return counts


def read_list(name):
    """Lines 'test name,result' (fails) or 'regex # reason' (skips, flakes); '#' starts a comment line."""
    path = os.path.join(EXPECTATIONS, name)
    entries = {}
    if not os.path.exists(path):
        return entries
    for line in open(path):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        text = line.split(" # ")[0].strip()
        if "," in text:
            test, result = text.rsplit(",", 1)
            entries[test.strip()] = result.strip().lower()
        else:
            entries[text] = "skip"
    return entries


def passes_on_retry(test, platform, env):
    """Runs one test's recorded command again; True when it passes this time."""
    cmd = test.get("command", "").split()
    if not cmd:
        return False
    if platform != "surfaceless_egl":
        # -noreset: without it Xvfb resets whenever its last client leaves, and a client that
        # connects during the reset gets "XOpenDisplay failed". With -j 2 and short tests that
        # happens several times a run, GL or not (plain Xlib programs hit it too).
        cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24 -noreset"] + cmd
    env = dict(env, PIGLIT_PLATFORM=platform)
    try:
        out = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=120).stdout
    except subprocess.TimeoutExpired:
        return False
    return '"result": "pass"' in out


def check_expectations(tests, platform):
    fails = read_list(f"{platform}-fails.txt")
    skips = [re.compile(p) for p in read_list(f"{platform}-skips.txt")]    # regexes, as in Mesa's CI
    flakes = [re.compile(p) for p in read_list(f"{platform}-flakes.txt")]
    regressions, unexpected_passes, changed = [], [], []
    for name, t in sorted(tests.items()):
        result = t["result"]
        if any(f.match(name) for f in flakes):
            continue
        expected_skip = any(s.match(name) for s in skips)
        if expected_skip and result == "skip":
            continue
        expected = fails.get(name, "skip" if expected_skip else "pass")
        if result == expected:
            continue
        if result == "pass":
            unexpected_passes.append((name, expected))
        elif expected == "pass":
            regressions.append((name, result))
        else:
            changed.append((name, expected, result))
    return regressions, unexpected_passes, changed


def cause_of(test):
    """The line of a test's output that says why it did not pass."""
    lines = [l.split("PIGLIT:")[0].strip() for l in (test.get("out", "") + "\n" + test.get("err", "")).splitlines()]
    lines = [l for l in lines if l and not l.startswith("PIGLIT:") and "Failed to create any GL context" not in l]
    for l in lines:  # piglit's own reasons first
        if l.startswith(("piglit: error:", "Test requires", "Function \"")) or "GetProcAddress failed" in l:
            return l
    if test["result"] == "timeout":
        return "time limit exceeded"
    if test["result"] == "crash":
        return f"crash (exit status {test.get('returncode')})"
    return lines[-1][:160] if lines else f"{test['result']} without output"


def write_expectations(tests, platform, groups):
    """Rewrites the fails and skips lists from this run, each test under its cause."""
    by_cause = {"fail": {}, "skip": {}}
    for name, t in sorted(tests.items()):
        if t["result"] in ("pass", "notrun"):
            continue
        kind = "skip" if t["result"] == "skip" else "fail"
        by_cause[kind].setdefault(cause_of(t), []).append((name, t["result"]))
    header = (f"# Written by conformance/run.py --update-expectations from a run of {', '.join(groups)}\n"
              f"# on Pineda, platform {platform}; each test under the output line that says why.\n")
    with open(os.path.join(EXPECTATIONS, f"{platform}-fails.txt"), "w") as f:
        f.write("# Tests that do not pass, as 'test name,result' (Mesa CI convention).\n" + header)
        for cause, names in sorted(by_cause["fail"].items()):
            f.write(f"\n# {cause}\n" + "".join(f"{n},{r}\n" for n, r in names))
    with open(os.path.join(EXPECTATIONS, f"{platform}-skips.txt"), "w") as f:
        f.write("# Tests piglit skips, as regexes (Mesa CI convention).\n" + header)
        for cause, names in sorted(by_cause["skip"].items()):
            f.write(f"\n# {cause}\n" + "".join(f"^{re.escape(n)}$\n" for n, _ in names))
    print(f"expectations rewritten: conformance/expectations/{platform}-{{fails,skips}}.txt")


def print_table(columns, groups):
    kinds = ("pass", "fail", "crash", "timeout", "skip")
    header = f"{'group':32}" + "".join(f" | {name:>34}" for name, _ in columns)
    print(header)
    print(f"{'':32}" + "".join(" | " + " ".join(f"{k:>6}" for k in kinds) for _ in columns))
    for g in groups:
        row = f"{g:32}"
        for _, counts in columns:
            c = counts.get(g, {})
            other = sum(v for k, v in c.items() if k not in kinds)
            row += " | " + " ".join(f"{c.get(k, 0) + (other if k == 'fail' else 0):>6}" for k in kinds)
        print(row)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--group", action="append", required=True, help="piglit group, e.g. 'spec@!opengl 1.1'")
    p.add_argument("--platform", choices=PLATFORMS, default="x11_egl")
    p.add_argument("--driver", choices=("pineda", "llvmpipe"), default="pineda")
    p.add_argument("--compare", choices=("llvmpipe",), help="also run on llvmpipe and show both")
    p.add_argument("--profile", default="quick")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--timeout", type=int, default=120)
    p.add_argument("--exclude", action="append", default=[], help="regex of tests to leave out")
    p.add_argument("--expected-total", type=int, default=0, help="test count, for the progress estimate")
    p.add_argument("--html", action="store_true", help="also write piglit's HTML summary")
    p.add_argument("--lib-dir", default=os.path.join(ROOT, "build", "lib"))
    p.add_argument("--via", choices=("library-path", "vendor"), default="library-path",
                   help="how piglit reaches Pineda: its libraries first on the library path, or the "
                        "system's libglvnd with Pineda as the vendor (LIB_DIR/glvnd)")
    p.add_argument("--update-expectations", action="store_true",
                   help="rewrite the fails and skips lists from this run (review the diff before committing)")
    p.add_argument("--results", help="use this earlier results folder instead of running piglit")
    args = p.parse_args()

    ensure_installed()
    runs = [args.driver] + ([args.compare] if args.compare and args.compare != args.driver else [])
    if "llvmpipe" in runs:
        ensure_llvmpipe()
    results = {}
    for driver in runs:
        if args.results and driver == args.driver:
            tests, results_dir, elapsed = load_results(args.results), args.results, 0.0
        else:
            tests, results_dir, elapsed = run_piglit(driver, args.platform, args.group, args, args.lib_dir)
        results[driver] = tests
        print(f"[{driver}] {len(tests)} tests in {elapsed:.0f}s; results in {results_dir}")
        if args.html:
            html = os.path.join(results_dir, "html")
            subprocess.run(["piglit", "summary", "html", "-o", html, results_dir], check=False)
            print(f"[{driver}] HTML report: {html}/index.html")

    print()
    print_table([(d, whole_test_counts(results[d], args.group)) for d in runs], args.group)

    if "pineda" in results and "llvmpipe" in results:
        pin, llv = results["pineda"], results["llvmpipe"]
        only_llvmpipe = sorted(n for n, t in llv.items() if t["result"] == "pass" and pin.get(n, {}).get("result") != "pass")
        only_pineda = sorted(n for n, t in pin.items() if t["result"] == "pass" and llv.get(n, {}).get("result") != "pass")
        print(f"\npassing on llvmpipe, not on Pineda ({len(only_llvmpipe)}):")
        for n in only_llvmpipe:
            print(f"  {n}: {pin.get(n, {}).get('result', 'not run')}")
        print(f"passing on Pineda, not on llvmpipe ({len(only_pineda)}):")
        for n in only_pineda:
            print(f"  {n}: {llv.get(n, {}).get('result', 'not run')}")

    if args.driver != "pineda":
        return 0
    if args.update_expectations:
        write_expectations(results["pineda"], args.platform, args.group)
    regressions, unexpected, changed = check_expectations(results["pineda"], args.platform)
    env = driver_env("pineda", args.platform, args.lib_dir, args.via)
    flaky = [(n, r) for n, r in regressions if passes_on_retry(results["pineda"][n], args.platform, env)]
    regressions = [x for x in regressions if x not in flaky]
    for name, result in flaky:
        print(f"FLAKE: {name}: {result}, then pass on retry")
    for name, result in regressions:
        print(f"REGRESSION: {name}: {result} (expected pass)")
    for name, expected in unexpected:
        print(f"UNEXPECTED PASS: {name} (listed as {expected}): update conformance/expectations/")
    for name, expected, result in changed:
        print(f"CHANGED: {name}: {result} (listed as {expected})")
    ok = not regressions and not unexpected and not changed
    print(f"\nexpectations: {'met' if ok else 'NOT met'} ({len(regressions)} regressions, "
          f"{len(unexpected)} unexpected passes, {len(changed)} changed)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
