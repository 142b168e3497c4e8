"""Small harness for the case tests: named checks, a summary line per test
('N passed, N failed'), exit code 1 on any failure."""
import os
import sys

project_dir = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))


class CaseTest:
    def __init__(self, name):
        self.name = name
        self.passed = 0
        self.failed = 0

    def check(self, what, ok, detail=""):
        if ok:
            self.passed += 1
            print("[  PASS  ] %s: %s" % (self.name, what))
        else:
            self.failed += 1
            print("[  FAIL  ] %s: %s" % (self.name, what))
            if detail:
                print("           " + detail.replace("\n", "\n           "))
        sys.stdout.flush()

    def check_equal(self, what, value, expected):
        self.check(what, value == expected,
                   "got %r, expected %r" % (value, expected))

    def check_close(self, what, value, expected, rtol):
        ok = abs(value - expected) <= rtol * abs(expected)
        self.check(what + " (rtol %g)" % rtol, ok,
                   "got %.10g, expected %.10g" % (value, expected))

    def finish(self):
        print("%s: %d passed, %d failed" % (self.name, self.passed, self.failed))
        return 0 if self.failed == 0 else 1
