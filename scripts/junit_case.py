"""One JUnit test case written by a check script of make test (catkin_lint_check.py, install_check.py,
readme_check.py), which scripts/test_summary.py then counts with the rest."""
import os
import sys
import traceback
from xml.sax.saxutils import escape, quoteattr


def out_path(doc):
    """The OUT.xml argument of `script OUT.xml`; prints `doc` and exits for -h/--help or a bad call."""
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(doc)
        sys.exit(0 if len(sys.argv) == 2 else 2)
    out = sys.argv[1]
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    return out


def write(out, suite, case, failure=None, details=""):
    """The case `suite`.`case`, passed, or failed with the message `failure` and `details`."""
    body = "" if failure is None else "<failure message=%s>%s</failure>" % (quoteattr(failure), escape(details))
    with open(out, "w") as f:
        f.write('<?xml version="1.0" encoding="utf-8"?>\n<testsuite name="%s" tests="1" failures="%d">'
                '<testcase classname="%s" name="%s">%s</testcase></testsuite>\n'
                % (suite, 0 if failure is None else 1, suite, case, body))


def run(doc, suite, case, checks, ok_text):
    """The whole check script: each of `checks` is called with a function that records a finding (a crash
    is a finding too); writes the case to OUT.xml, prints the findings or `ok_text`, returns the exit status."""
    out = out_path(doc)
    findings = []
    for check in checks:
        try:
            check(findings.append)
        except Exception:
            findings.append(traceback.format_exc())
    write(out, suite, case, "%d %s finding(s)" % (len(findings), suite) if findings else None, "\n".join(findings))
    print("%s: %s" % (case, ok_text if not findings else "\n" + "\n".join(findings)))
    return 1 if findings else 0
