"""What the checkBounds*.sh shell tests of this directory share: the Python they run on the tutorials'
check functions (issue 45's rule on broken inputs: no simulation, plain numbers). Each script runs
its Python with this directory and etc/python on PYTHONPATH and imports from here:

    load = tutorial_loader(src, "channel")          # load(name, case, script, group): a module
    expect(what, passes, add)                       # one expectation: an 'ok' or 'WRONG' line
    broken(what, add, good, bound_value, noisy)     # a good value passes, its broken variants fail
    print_summary()                                 # 'N wrong' (the script's shell side reads it)

Not a test itself: tests/CMakeLists.txt takes tests/apps/*.sh as tests, and tests/python/test_*.py.
"""
import importlib.util
import math
import sys

from dpdfoam.checks import Checks

NAN, INF = float("nan"), math.inf
ok_count, wrong = 0, 0


def tutorial_loader(src, group):
    """load(name, case, script="plotResults.py", group=group): a tutorial's script under
    src/tutorials/group/case as module `name`."""
    def load(name, case, script="plotResults.py", group=group):
        """A tutorial's script (plotResults.py unless said) as module `name`, its directory on sys.path
        while it loads (the lattice-wall script imports wallComparison beside it)."""
        directory = f"{src}/tutorials/{group}/{case}"
        sys.path.insert(0, directory)
        try:
            spec = importlib.util.spec_from_file_location(name, f"{directory}/{script}")
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
        finally:
            sys.path.remove(directory)
        return module
    return load


def expect(what, passes, add):
    """add(checks) adds one check or several: all must pass, or (passes False) one at least must fail.
    A check that raises is wrong either way (a check must decide, not raise: the tutorial's script
    would stop without its table)."""
    global ok_count, wrong
    checks, raised = Checks(), None
    try:
        add(checks)
    except Exception as e:
        raised = f"raised {type(e).__name__}: {e}"
        checks.add(raised, False)
    passed = bool(checks.rows) and not checks.failures()
    ok = passed == passes and raised is None
    ok_count += ok
    wrong += not ok
    print(f"{'ok   ' if ok else 'WRONG'} {'pass' if passes else 'fail'}  {what}" +
          ("" if ok else "   <- " + " | ".join(checks.lines())))


def broken(what, add, good, bound_value, noisy, inf=False):
    """add(checks, value, error, *rest); good: arguments that pass. Each broken variant fails: the value
    NaN (inf too, with inf), empty or missing, the error NaN, missing or `noisy` (over its budget), the
    value `bound_value` (just outside the bound)."""
    expect(f"{what}: good", True, lambda c: add(c, *good))
    for name, value in (("NaN", NAN),) + ((("inf", INF),) if inf else ()) + (("empty", ""), ("missing", None)):
        expect(f"{what}: value {name}", False, lambda c: add(c, value, *good[1:]))
    expect(f"{what}: error NaN", False, lambda c: add(c, good[0], NAN, *good[2:]))
    expect(f"{what}: error missing", False, lambda c: add(c, good[0], None, *good[2:]))
    expect(f"{what}: error over its budget", False, lambda c: add(c, good[0], noisy, *good[2:]))
    expect(f"{what}: just outside the bound", False, lambda c: add(c, bound_value, *good[1:]))


def print_summary(count_ok=False):
    """The last line: 'N wrong', or with count_ok 'M ok, N wrong'."""
    print(f"{ok_count} ok, {wrong} wrong" if count_ok else f"{wrong} wrong")
