"""The examples in the docstrings run and print what they claim."""

import doctest

import bezsurf.bspline
import bezsurf.patch


def load_tests(loader, tests, ignore):
    tests.addTests(doctest.DocTestSuite(bezsurf.patch))
    tests.addTests(doctest.DocTestSuite(bezsurf.bspline))
    return tests
