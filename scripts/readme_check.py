#!/usr/bin/python3
"""The README's commands exist, as one JUnit test case (make test counts it).

Usage: readme_check.py OUT.xml
Every command line of README.md (in its sh code blocks, and inline `...` spans that start with a
command) is checked against the workspace, so that a newcomer can copy and paste it:
  make TARGET [VAR=...]            the Makefile has the target;
  roslaunch PKG FILE [arg:=v ...]  PKG/launch/FILE exists and declares every arg given;
  rosrun PKG EXE [--opt ...]       EXE is built (devel/lib/PKG) or a script of PKG, and every --option
                                   given appears in its --help;
  rviz/..., scripts/...            the file exists and is executable;
  a bare stack executable          is refused: it is not on the PATH (rosrun PKG EXE is).
Placeholders (FILE, LOG.csv, ...) and shell builtins are not checked. Needs a built workspace.
Exit status 1 on a finding.
"""
import glob
import os
import re
import shlex
import subprocess
import sys

import junit_case

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PKG_DIR = {"asv_core": "src"}
COMMANDS = ("make", "roslaunch", "rosrun", "rviz/", "scripts/")


def commands(text):
    """(line number, command) of every command line in sh blocks and inline spans."""
    out = []
    in_block = False
    lines = text.splitlines()
    for n, line in enumerate(lines, 1):
        if line.strip().startswith("```"):
            in_block = not in_block and line.strip() in ("```sh", "```bash")
            continue
        if in_block:
            cmd = line.split("  #")[0].strip().rstrip("\\").strip()
            if cmd and not cmd.startswith("#"):
                out.append((n, cmd))
        else:
            out += [(n, c) for c in re.findall(r"`([^`]+)`", line) if c.startswith(COMMANDS)]
    return out


def executables():
    """Every executable the workspace builds, by name."""
    found = {}
    for path in glob.glob(os.path.join(ROOT, "devel", "lib", "*", "*")) + \
            glob.glob(os.path.join(ROOT, "devel", "lib", "*", "bench", "*")):
        if os.access(path, os.X_OK) and os.path.isfile(path):
            found.setdefault(os.path.basename(path), path)
    return found


def check_make(words, makefile):
    target = words[1] if len(words) > 1 else ""
    if not target or "=" in target:
        return None
    return None if re.search(r"^%s:" % re.escape(target), makefile, re.M) else "no make target '%s'" % target


def check_roslaunch(words):
    if len(words) < 3:
        return None
    pkg, name = words[1], words[2]
    path = os.path.join(ROOT, PKG_DIR.get(pkg, pkg), "launch", name)
    if not os.path.exists(path):
        return "no launch file %s/launch/%s" % (pkg, name)
    with open(path) as f:
        declared = set(re.findall(r'<arg\s+name="([^"]+)"', f.read()))
    for w in words[3:]:
        if ":=" in w and w.split(":=")[0] not in declared:
            return "%s declares no argument '%s'" % (name, w.split(":=")[0])
    return None


def check_rosrun(words, built):
    if len(words) < 3:
        return None
    pkg, exe = words[1], words[2]
    script = os.path.join(ROOT, PKG_DIR.get(pkg, pkg), "scripts", exe)
    path = os.path.join(ROOT, "devel", "lib", pkg, exe)
    if not os.access(path, os.X_OK) and not os.access(script, os.X_OK):
        return "rosrun %s %s: no such executable" % (pkg, exe)
    options = [w.split("=")[0] for w in words[3:] if w.startswith("--")]
    if not options:
        return None
    run = path if os.access(path, os.X_OK) else script
    try:
        text = subprocess.run([run, "--help"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=60).stdout
    except (OSError, subprocess.SubprocessError) as e:
        return "%s --help failed: %s" % (exe, e)
    missing = [o for o in options if o not in text]
    return "%s --help does not know %s" % (exe, ", ".join(missing)) if missing else None


def check_file(words):
    path = os.path.join(ROOT, words[0])
    if words[0].endswith("/"):
        return None if os.path.isdir(path) else "no folder %s" % words[0]
    if not os.path.exists(path):
        return "no file %s" % words[0]
    if words[0].endswith((".sh", ".py")) and not os.access(path, os.X_OK):
        return "%s is not executable" % words[0]
    return None


def check(cmd, makefile, built):
    try:
        words = shlex.split(cmd)
    except ValueError:
        words = cmd.split()
    if not words:
        return None
    head = words[0]
    if head == "make":
        return check_make(words, makefile)
    if head == "roslaunch":
        return check_roslaunch(words)
    if head == "rosrun":
        return check_rosrun(words, built)
    if head.startswith(("rviz/", "scripts/")):
        return check_file(words)
    if head in built:
        return "'%s' is not on the PATH: write rosrun <package> %s" % (head, head)
    return None


def main():
    out = junit_case.out_path(__doc__)
    with open(os.path.join(ROOT, "README.md")) as f:
        text = f.read()
    with open(os.path.join(ROOT, "Makefile")) as f:
        makefile = f.read()
    built = executables()
    cmds = commands(text)
    findings = ["README.md:%d: %s: %s" % (n, c, why) for n, c in cmds for why in [check(c, makefile, built)] if why]
    junit_case.write(out, "readme", "commands_exist",
                     "%d README command(s) do not exist" % len(findings) if findings else None, "\n".join(findings))
    print("readme_check: %d commands, %s" % (len(cmds), "all exist" if not findings else "\n" + "\n".join(findings)))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
