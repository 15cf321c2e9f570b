#!/usr/bin/python3
"""make lint: clang-tidy with the root .clang-tidy over every C++ source of the stack in
build/compile_commands.json (generated sources in build/ left out), JOBS files at a time.

Usage: lint.py [JOBS]     (environment: ASV_LINT_CACHE, the cache folder, default ~/.cache/asv/lint;
                           none: no cache)
Prints each finding and a summary line; exit status 1 on any finding.

A file found clean is remembered, as ccache remembers a compilation: by a hash of its compile command
and of the text of every file it includes (the clone's folder replaced, so that clones share the cache),
of .clang-tidy and of clang-tidy's version. It is linted again only when one of them changed: a header,
a flag, a comment (readability-function-size counts lines), a check. The included files are those of
the build's dependency file (<object>.d, written with the object), as ccache's direct mode reads them;
when it is missing or older than the source, the key is the hash of the preprocessed text instead
(preprocessing every file took nearly three minutes on 2 cores, hashing the files a few seconds).
Findings are never cached: a file with one is linted every time.
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


DIGESTS = {}  # path -> sha256 of its bytes, shared by the jobs (a header is read once)


def digest(path):
    if path not in DIGESTS:
        with open(path, "rb") as f:
            DIGESTS[path] = hashlib.sha256(f.read()).digest()
    return DIGESTS[path]


def dependencies(entry):
    """The files the entry's object was compiled from (its .d file), or None when that file is missing
    or older than the source (the object is not from this text)."""
    args = shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])
    if "-o" not in args:
        return None
    depfile = os.path.join(entry["directory"], args[args.index("-o") + 1] + ".d")
    try:
        if os.path.getmtime(depfile) < os.path.getmtime(entry["file"]):
            return None
        with open(depfile) as f:
            text = f.read().replace("\\\n", " ")
    except OSError:
        return None
    _, _, deps = text.partition(": ")
    return [os.path.normpath(os.path.join(entry["directory"], d)) for d in deps.split()]


def direct_key(entry, salt):
    deps = dependencies(entry)
    if not deps:
        return None
    h = hashlib.sha256(salt + b"direct\0")
    h.update(" ".join(preprocess_command(entry)).replace(ROOT, "<root>").encode())
    try:
        for d in deps:
            h.update(b"\0" + d.replace(ROOT, "<root>").encode() + b"\0" + digest(d))
    except OSError:
        return None  # a file of the last build is gone
    return h.hexdigest()


def cache_key(entry, salt):
    key = direct_key(entry, salt)
    if key:
        return key
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
