"""Library status codes as Python exceptions: every failure of librelcol (a negative
rc_status) becomes a RelcolError carrying the library's own message (rc_strerror), its
code and its name, and, for a batch, the index of the item that failed."""
from ._relcol import ffi, lib

# The names of the codes (relcol/status.h), for messages and for `except` clauses that
# test e.code == relcol.RC_ESPEED and the like.
CODES = {
    0: "RC_OK", 1: "RC_NO_COLLISION", 2: "RC_MISS",
    -1: "RC_EINVAL", -2: "RC_ENONFINITE", -3: "RC_EMASS", -4: "RC_ESPEED",
    -5: "RC_ERESTITUTION", -6: "RC_ESPEEDOFLIGHT", -7: "RC_EZERONORMAL",
    -8: "RC_EOVERLAP", -9: "RC_ENOMEM", -10: "RC_ENOCONVERGE", -11: "RC_EUNKNOWN",
    -12: "RC_ERADIUS", -13: "RC_EDIM", -14: "RC_ECORRUPT", -15: "RC_EMISMATCH",
    -16: "RC_ESTALL", -17: "RC_ENOTREADY", -18: "RC_ENOSLICE", -19: "RC_ESCALE",
    -20: "RC_EUNDEFINED",
}


class RelcolError(Exception):
    """A failure reported by librelcol.

    code    the status code (negative), e.g. -4
    name    its name, e.g. "RC_ESPEED"
    reason  the library's text, rc_strerror(code), e.g. "speed must be < c"
    index   the pair or ball that failed in a batch call, else None
    field   the argument that is wrong, as "m[3]" or "c", where known, else None
    """

    def __init__(self, code, context=None, index=None, field=None):
        self.code = int(code)
        self.name = CODES.get(self.code, "RC_%d" % self.code)
        self.reason = strerror(self.code)
        self.index = index
        self.field = field
        where = "" if index is None or field is not None else " (item %d)" % index
        if field is not None:
            context = "%s: %s" % (context, field) if context else field
        head = "%s%s: " % (context, where) if context else (where.strip() + ": " if where else "")
        super().__init__("%s%s [%s]" % (head, self.reason, self.name))


def strerror(code):
    """The library's description of a status code."""
    return ffi.string(lib.rc_strerror(int(code))).decode()


def check(code, context=None, index=None):
    """Raise RelcolError for a failure code; return the code otherwise (0, or an
    informational outcome such as RC_MISS)."""
    if code < 0:
        raise RelcolError(code, context, index)
    return code


def check_field(code, context=None, index=None, field=None):
    """check() naming the argument that is wrong (e.g. "m1[3]")."""
    if code < 0:
        raise RelcolError(code, context, index, field)
    return code


def shape_error(func, name, got, want):
    """ValueError naming the argument whose array has the wrong shape."""
    return ValueError("%s: %s: has shape %s, expected %s" % (func, name, tuple(got), want))


class ScenarioError(ValueError):
    """A scenario the reader refuses: the message is relcol-sim's, "NAME: PATH: reason";
    path is the JSON path of the wrong value ("balls[3].v"), reason the rest."""

    def __init__(self, message):
        super().__init__(message)
        parts = message.split(": ", 2)
        self.path = parts[1] if len(parts) == 3 else None
        self.reason = parts[-1]
