import os

# The benchmarks and tests measure one core; OpenBLAS threads only add noise here.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

from hypothesis import settings  # noqa: E402

# Property tests draw 40 examples each.  A developer's run draws them afresh every time (that
# is how the edge cases found so far were found); .ci/run sets ASPERITY_HYPOTHESIS_DERANDOMIZE=1
# so that the gate is the same run a developer's dry run of .ci/run was: a case found by a
# random draw becomes a fix and a test, not a red gate on one machine and a green one on the
# next.  ASPERITY_HYPOTHESIS_EXAMPLES=N draws more, for a hunt (with --hypothesis-seed=S).
settings.register_profile(
    "ci",
    max_examples=int(os.environ.get("ASPERITY_HYPOTHESIS_EXAMPLES", "40")),
    deadline=None,
    **({"derandomize": True, "database": None} if os.environ.get("ASPERITY_HYPOTHESIS_DERANDOMIZE") == "1" else {}),
)
settings.load_profile("ci")
