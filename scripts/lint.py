#!/usr/bin/python3
"""make lint: clang-tidy with the root .clang-tidy over every C++ source of the stack in
build/compile_commands.json (generated sources in build/ left out), JOBS files at a time.

Usage: lint.py [JOBS]     (environment: ASV_LINT_CACHE, the cache folder, default ~/.cache/asv/lint;
                           none: no cache)
Prints each finding and a summary line; exit status 1 on any finding.

A file found clean is remembered, as ccache remembers a compilation: by a hash of its preprocessed
text with comments (the clone's folder replaced, so that clones share the cache), of .clang-tidy and of
clang-tidy's version. It is linted again only when one of them changed: a header, a macro, a comment
(readability-function-size counts lines), a check. Findings are never cached: a file with one is
linted every time.
"""
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
DB = os.path.join(ROOT, "build", "compile_commands.json")
FINDING = re.compile(r"(warning|error): .*\[[a-z]+-")


def preprocess_command(entry):
    """The entry's compile command with -E -C instead of -c and no output file or launcher."""
    args = shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])
    if os.path.basename(args[0]) == "ccache":
        args = args[1:]
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        elif a == "-c":
            out += ["-E", "-C"]
        else:
            out.append(a)
    return out


def cache_key(entry, salt):
    p = subprocess.run(preprocess_command(entry), cwd=entry["directory"], capture_output=True)
    if p.returncode != 0:
        return None  # let clang-tidy say what is wrong
    text = p.stdout.replace(ROOT.encode(), b"<root>")
    return hashlib.sha256(salt + text).hexdigest()


def lint(entry, cache, salt):
    """(file, findings, output): from the cache when the file's key is there, else from clang-tidy."""
    key = cache_key(entry, salt) if cache else None
    stamp = os.path.join(cache, key) if key else None
    if stamp and os.path.exists(stamp):
        return entry["file"], [], ""
    p = subprocess.run(["clang-tidy", "-p", os.path.dirname(DB), "--quiet", entry["file"]], cwd=ROOT,
                       capture_output=True, text=True)
    output = p.stdout + p.stderr
    findings = sorted({l.replace(ROOT + "/", "") for l in output.splitlines() if FINDING.search(l)})
    if p.returncode != 0 and not findings:
        findings = ["%s: clang-tidy failed (exit %d)" % (entry["file"], p.returncode)]
    if stamp and not findings:
        open(stamp, "w").close()
    return entry["file"], findings, output


def main():
    jobs = int(sys.argv[1]) if len(sys.argv) > 1 else 2
    if not os.path.isfile(DB):
        print("lint: %s missing (make build writes it)" % DB)
        return 1
    entries = {}
    for e in json.load(open(DB)):
        if "/build/" not in e["file"]:
            entries.setdefault(e["file"], e)
    cache = os.environ.get("ASV_LINT_CACHE", os.path.expanduser("~/.cache/asv/lint"))
    if cache == "none":
        cache = None
    else:
        os.makedirs(cache, exist_ok=True)
    version = subprocess.run(["clang-tidy", "--version"], capture_output=True, text=True).stdout
    salt = (version + open(os.path.join(ROOT, ".clang-tidy")).read()).encode()
    print("lint: clang-tidy on %d files with %d jobs (cache %s) ..." % (len(entries), jobs, cache or "off"),
          flush=True)
    findings, log = [], []
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        for f, found, output in pool.map(lambda e: lint(e, cache, salt), sorted(entries.values(),
                                                                                 key=lambda e: e["file"])):
            findings += found
            if output:
                log.append(output)
    with open(os.path.join(ROOT, "build", "lint.log"), "w") as f:
        f.write("\n".join(log))
    for line in sorted(set(findings)):
        print(line)
    print("lint: %d files, %d finding(s)" % (len(entries), len(set(findings))))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
