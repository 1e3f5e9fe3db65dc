"""The numpy replica of the pixels' gather (Testing/Reference/gather_replica.py) still traces
what the shaders trace: on the small emitter's room's floor (albedo 0.6), with `Bounces` 0,
its gather times the albedo is the pass's indirect light within 10 % (measured 0.90), and a
point off the image gives no pixel to compare.

    python3 test_gather_replica.py Testing/Reference/gather_replica.py
"""
import importlib.util
import sys

import numpy as np

spec = importlib.util.spec_from_file_location("gather_replica", sys.argv[1])
replica = importlib.util.module_from_spec(spec)
spec.loader.exec_module(replica)

gather, indirect = replica.replica_and_pass("emitterroom", np.array([2.5, 0.0, 2.0]),
                                            np.array([0.0, 1.0, 0.0]))
ratio = 0.6 * gather.mean() / indirect.mean()
print("replica x albedo / the pass's indirect light: %.3f" % ratio)
failures = []
if not abs(ratio - 1.0) <= 0.1:
    failures.append("the replica no longer matches the pass: %.3f" % ratio)
_, off = replica.replica_and_pass("emitterroom", np.array([2.5, 0.0, 5.9]),
                                  np.array([0.0, 1.0, 0.0]))
if off is not None:
    failures.append("a point below the camera gave a pixel")
for f in failures:
    print("FAILED: " + f)
sys.exit(1 if failures else 0)
