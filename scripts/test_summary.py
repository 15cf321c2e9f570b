#!/usr/bin/python3
"""Summarise the JUnit XML results of `catkin_make run_tests` (and any other runner writing JUnit XML).

Usage: test_summary.py RESULTS_DIR [--expect N]
Prints each failing test case with its message, then the closing line `N passed, N failed, N skipped`.
Exit status 1 when anything failed, when a test binary left no result (catkin writes a MISSING-RESULT
failure for those), or when fewer than --expect result files were found.
rostest writes two files per launch file: the gtest cases (rosunit-*.xml) and a summary
(rostest-*.xml) whose single case repeats them; the summary is read only for launch-level failures
(a node that died, a test that never reported).
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def cases(path):
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        yield (os.path.basename(path), "unparsable result file: %s" % e, False)
        return
    for tc in root.iter("testcase"):
        name = "%s.%s" % (tc.get("classname", ""), tc.get("name", ""))
        bad = tc.find("failure")
        if bad is None:
            bad = tc.find("error")
        skipped = tc.find("skipped") is not None or tc.get("status") == "notrun"
        if bad is not None:
            yield (name, (bad.get("message") or bad.text or "failed").strip(), False)
        else:
            yield (name, "skipped" if skipped else None, skipped)


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    root = sys.argv[1]
    expect = int(sys.argv[sys.argv.index("--expect") + 1]) if "--expect" in sys.argv else 0
    files = sorted(glob.glob(os.path.join(root, "**", "*.xml"), recursive=True))
    passed = failed = skipped = 0
    for f in files:
        base = os.path.basename(f)
        rostest_summary = base.startswith("rostest-")
        for name, msg, is_skip in cases(f):
            if rostest_summary:
                if msg is not None and not is_skip:
                    failed += 1
                    print("FAILED %s (%s): %s" % (name, base, msg.splitlines()[0][:300]))
                continue
            if is_skip:
                skipped += 1
            elif msg is None:
                passed += 1
            else:
                failed += 1
                print("FAILED %s (%s): %s" % (name, base, msg.splitlines()[0][:300]))
    if len(files) < expect:
        print("FAILED: only %d result files, expected at least %d" % (len(files), expect))
        failed += 1
    if not files:
        print("FAILED: no test results found under %s" % root)
        failed += 1
    print("%d passed, %d failed, %d skipped" % (passed, failed, skipped))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
