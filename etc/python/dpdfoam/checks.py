"""The checks' bookkeeping: each check a name, a verdict (PASS, FAIL or info) and the measured value as
text; a check whose numbers hold a NaN or a missing value (None) fails whatever its comparison says.

    checks = Checks()
    checks.add("nu within 3 %", abs(rel) < 0.03, f"{100 * rel:+.2f} %", rel)
    checks.bounded("nu within 3 % (error below 1 %)", rel, err, 0.01, -0.03, 0.03)  # issue 45's form
    checks.within_budgets("nu within 3 budgets", rel, err, 0.01)  # the same, its bounds in budgets
    checks.write(f)                  # 'check  PASS  nu within 3 %: +0.41 %' lines
    return checks.status()           # the script's exit status: 1 when a check failed
"""
import math
import sys

from .io import write_whole


def finite(value):
    """Whether a number (or each of a sequence, not empty: an empty one is no measurement) is there and
    finite."""
    if value is None:
        return False
    if isinstance(value, (list, tuple)):
        return len(value) > 0 and all(finite(v) for v in value)
    try:
        return math.isfinite(float(value))
    except (TypeError, ValueError):
        return False


def as_number(value):
    """value as a float; NaN for a missing (None), empty or non-numeric value, which then fails the
    check that reads it (arithmetic on a None or a string would raise instead)."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return float("nan")


def _text(value):
    try:
        return f"{float(value):.4g}"
    except (TypeError, ValueError):
        return repr(value)


def bounded_verdict(value, error, budget, lower=None, upper=None):
    """issue 45's verdict on a measured value with its standard error: (passed, why). Passes when
    every number is finite, error < budget, and lower <= value <= upper (a None bound is open)."""
    bounds = [b for b in (lower, upper) if b is not None]
    if not finite([value, error, budget] + bounds):
        return False, (f"value {_text(value)}, standard error {_text(error)}, budget {_text(budget)}, bounds "
                       f"[{_text(lower)}, {_text(upper)}]: not a finite number")
    value, error, budget = float(value), float(error), float(budget)
    if not error < budget:
        return False, f"standard error {error:.4g} ABOVE its budget {budget:.4g}: too noisy to decide"
    inside = (lower is None or value >= lower) and (upper is None or value <= upper)
    where = " and ".join(w for w in ((f">= {lower:.4g}" if lower is not None else ""),
                                     (f"<= {upper:.4g}" if upper is not None else "")) if w)
    return inside, (f"{value:+.4g} {'within' if inside else 'OUTSIDE'} the bound ({where}), standard error "
                    f"{error:.4g} below its budget {budget:.4g}")


class Checks:
    def __init__(self):
        self.rows = []  # (name, verdict, value text)

    def add(self, name, passed, value="", *numbers):
        """A check: PASS when passed is true and every one of numbers (what the verdict reads) is finite."""
        ok = bool(passed) and all(finite(n) for n in numbers)
        self.rows.append((name, "PASS" if ok else "FAIL", value))
        return ok

    def extend(self, checks):
        """(name, passed, value) triples, as the published comparison gives them."""
        for name, passed, value in checks:
            self.add(name, passed, value)

    def include(self, other):
        """Another Checks object's checks, after these."""
        self.rows += other.rows

    def bounded(self, name, value, error, budget, lower=None, upper=None, text=""):
        """A statistical check (issue 45), one row: first the standard error within its budget (a run
        too noisy to decide fails, and the row names the budget), then the value within the fixed
        bounds lower <= value <= upper (None: no bound on that side), bounds set from the budget, never
        from the run's error. A NaN, inf, None or empty value, error, budget or bound fails. Returns
        whether it passed."""
        ok, verdict = bounded_verdict(value, error, budget, lower, upper)
        shown = f"{text}; " if text else ""
        return self.add(name, ok, f"{shown}{verdict}")

    def within_budgets(self, name, value, error, budget, text="", lower=-3.0, upper=3.0):
        """bounded with its bounds in budgets: lower x budget <= value <= upper x budget (None: no bound)."""
        return self.bounded(name, value, error, budget, None if lower is None else lower * budget,
                            None if upper is None else upper * budget, text)

    def near_zero(self, what, value, error, budget, text="", bound=3.0):
        """what's value within bound budgets of 0, the name saying the bound and the standard error's budget."""
        return self.within_budgets(f"{what} (within {bound:g} x {budget:g}, standard error below {budget:g})", value,
                                   error, budget, text, -bound, bound)

    def fail(self, message):
        """A failed check given by its message alone."""
        self.add(message, False)

    def inform(self, keep):
        """Turns every check whose name keep(name) refuses into information (reported, not decided)."""
        self.rows = [(n, v if keep(n) else "info", t) for n, v, t in self.rows]

    def failures(self):
        return [name for name, verdict, _ in self.rows if verdict == "FAIL"]

    def lines(self, template="check  {verdict}  {name}: {value}"):
        return [template.format(verdict=verdict, name=name, value=value) for name, verdict, value in self.rows]

    def write(self, f, template="check  {verdict}  {name}: {value}"):
        """The 'check  PASS  name: value' lines (or the template's) to an open results file."""
        for line in self.lines(template):
            f.write(line + "\n")

    def print_failures(self, summary=True):
        """'CHECK FAILED: name' per failed check, then whether all passed."""
        for name in self.failures():
            print("CHECK FAILED:", name)
        if summary and not self.failures():
            print("All checks passed.")

    def status(self):
        """The exit status: 0 when no check failed."""
        return 1 if self.failures() else 0


def mode_budget(budgets, kind, test):
    """A kind of check's standard-error budget of budgets {kind: (full size, test mode)}; NaN (fails) for none."""
    value = budgets.get(kind, (None, None))[1 if test else 0]
    return float("nan") if value is None else value


def plus_minus(value, error, digits=4, sign=""):
    """'value +- error' with digits decimals (sign "+": the value's sign always shown)."""
    return f"{value:{sign}.{digits}f} +- {error:.{digits}f}"


def relative_difference(value, error, reference, reference_error):
    """value / reference - 1 and its standard error (the two errors independent, relative to the
    reference); a missing or non-numeric number reads as NaN (as_number), which fails the check."""
    value, error, reference, reference_error = (as_number(v) for v in (value, error, reference, reference_error))
    return value / reference - 1.0, math.hypot(error, reference_error) / reference


def write_results(path, lines, checks=None):
    """A results file, written whole (dpdfoam.io.write_whole): the lines, then the checks' lines; printed
    as written."""
    write_whole(path, "".join(line + "\n" for line in list(lines) + (checks.lines() if checks is not None else [])))
    print_file(path)


def print_file(path):
    with open(path) as f:
        sys.stdout.write(f.read())
