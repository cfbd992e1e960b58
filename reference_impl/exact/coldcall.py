"""``cold(fn, nargs)``: call a rarely taken numba function without taxing the hot path.

    from reference_impl.exact.coldcall import cold
    _slow_stage = cold(_incircle_exact, 9)      # then, in an njit function: _slow_stage(ax, ..., w)

Why: every exact predicate is a float filter (a few dozen flops, inlined into the kernels)
followed by a call to an exact stage that almost never runs.  numba lowers that call with its
usual error propagation: if the callee raised, the caller returns at once.  That early return
is a path on which the caller's arrays are not released, and numba's reference-count pruning
pass (``refprune``) only forgives such paths when they are marked as raising.  numba's own
propagation does not mark them, so every array the kernel hands to an inlined predicate (the
mesh, the points, the workspace) keeps an ``NRT_incref``/``NRT_decref`` pair, two atomic
calls, around *every* predicate evaluation, taken or not.  Measured here: an in-circle test on
random points cost 31.7 ns with the plain call and 23.5 ns through ``cold`` (22.3 ns with no
exact stage at all); about 20% of a whole triangulation.

``cold`` returns a numba intrinsic that makes the same call and propagates an exception the
same way, but marks the propagating store as numba marks a ``raise`` (the
``numba_exception_output`` metadata), so the pruning pass removes the reference counting of
the hot path.  On that path (an exception from an exact stage: never expected) references may
leak, exactly as after any ``raise`` in numba code.  The callee is linked as usual, so the
callers' on-disk cache works unchanged.

Only for callers that are not inside a numba ``try`` block (the library has none).

>>> import numpy as np
>>> from numba import njit
>>> @njit
... def twice(x):
...     return 2 * x
>>> twice_cold = cold(twice, 1)
>>> @njit
... def use(x):
...     return twice_cold(x) + 1
>>> use(20)
41
"""
from __future__ import annotations

from llvmlite import ir
from numba.core import cgutils
from numba.extending import intrinsic

__all__ = ["cold"]

_MARK = "numba_exception_output"   # the metadata numba's refprune pass reads as "this path raises"


def _typed(dispatcher, argtys):
    """The signature and code generator of one call of ``dispatcher`` with ``argtys``."""
    argtys = tuple(argtys)
    dispatcher.compile(argtys)
    cres = dispatcher.overloads[argtys]

    def codegen(context, builder, signature, args):
        fndesc = cres.fndesc
        fn = context.declare_function(builder.module, fndesc)
        status, res = context.call_conv.call_function(builder, fn, fndesc.restype, fndesc.argtypes, args)
        with cgutils.if_unlikely(builder, status.is_error):
            excinfo = context.call_conv._get_excinfo_argument(builder.function)
            store = builder.store(status.excinfoptr, excinfo)
            store.set_metadata(_MARK, builder.module.add_metadata([ir.IntType(1)(1)]))
            builder.ret(status.code)
        context.add_linking_libs([cres.library])
        return res

    return cres.signature, codegen


def cold(dispatcher, nargs: int):
    """A numba intrinsic calling ``dispatcher`` (an ``@njit`` function of ``nargs`` arguments)
    through a call whose exception path does not pin the caller's arrays (module docstring)."""
    # numba types an intrinsic by the names of its parameters, so the arity is spelled out
    names = ", ".join(f"a{i}" for i in range(nargs))
    namespace = {"_typed": _typed, "dispatcher": dispatcher}
    exec(f"def call(typingctx, {names}):\n    return _typed(dispatcher, ({names},))\n", namespace)
    call = namespace["call"]
    call.__name__ = call.__qualname__ = f"cold_{dispatcher.__name__}"
    return intrinsic(call)
