#!/usr/bin/python3
"""The stability suite's coarse form (tests/stability/stability.py): every
method on its hardest cases, each invariant at every written time one
check; the summary line counts the invariants met and missed."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "stability"))
import stability  # noqa: E402

if __name__ == "__main__":
    sys.exit(stability.main(sys.argv[1:], "stabilitySuite"))
