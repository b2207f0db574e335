"""dead_reckoning_overhead.py: what calling the library from Python costs for 100 000 entities.

The entities are those of bench/bench_replication.cpp: mixed DIS models as games use them (45%
FPW, 40% RVW, 8% RPB, 7% RVB, every rotating one turning), positions within 1 km, updates between
0 and 0.25 s old. Two per-frame calls are timed, each against the same library call made from
C++ in the same process on the same entities (helpers compiled into the module):

  DeadReckoningBatch.extrapolate     vs DeadReckoningBatch::extrapolate (the fast path)
  predict_dead_reckoning_batch       vs predictDeadReckoningBatch (the Python call also
                                        converts the NumPy input arrays and returns new arrays):
                                        float64 arrays, then float32 ones (read as they are)

Rounds alternate Python and C++ blocks of calls, so that a busy machine slows both alike, and
each block runs in the steady state of its own call (the previous call left the same data in the
caches); the medians of the rounds' medians are printed.

  PYTHONPATH=build/bindings/python python3 bindings/python/bench/dead_reckoning_overhead.py
"""

import argparse
import statistics
import time

import numpy as np

import foresight as fs

NOW = 3600.0  # [s], an hour into the session


def entities(n, seed=6):
    rng = np.random.default_rng(seed)
    u = rng.uniform(0, 1, n)
    algorithms = np.select([u < 0.45, u < 0.85, u < 0.93], [2, 4, 7], 8)  # FPW, RVW, RPB, else RVB
    positions = np.stack([rng.uniform(-1000, 1000, n), rng.uniform(0, 50, n), rng.uniform(-1000, 1000, n)], axis=1)
    velocities = np.stack([rng.uniform(-10, 10, n), rng.uniform(-1, 1, n), rng.uniform(-10, 10, n)], axis=1)
    accelerations = np.stack([rng.uniform(-3, 3, n), rng.uniform(-9.81, 0, n), rng.uniform(-3, 3, n)], axis=1)
    angles = rng.uniform(-3.14, 3.14, n)
    orientations = np.stack([np.zeros(n), np.sin(angles / 2), np.zeros(n), np.cos(angles / 2)], axis=1)
    w = np.stack([rng.uniform(-0.2, 0.2, n), rng.uniform(-2, 2, n), rng.uniform(-0.2, 0.2, n)], axis=1)
    rotates = np.isin(algorithms, [3, 4, 7, 8])
    angular = np.where(rotates[:, None], w, 0.0)
    timestamps = NOW - rng.uniform(0, 0.25, n)
    return algorithms, positions, velocities, accelerations, orientations, angular, timestamps


def python_median(call, repeats):
    samples = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--entities", type=int, default=100000)
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--repeats", type=int, default=20, help="calls per round")
    args = parser.parse_args()

    arrays = entities(args.entities)
    batch = fs.DeadReckoningBatch(args.entities)
    batch.set_all(*arrays)

    single = [a.astype(np.float32) if i in (1, 2, 3, 4, 5) else a for i, a in enumerate(arrays)]
    rows = {"soa": ([], []), "batch": ([], []), "batch32": ([], [])}
    for _ in range(args.rounds):
        rows["soa"][0].append(python_median(lambda: batch.extrapolate(NOW, 0.25), args.repeats))
        rows["soa"][1].append(batch._time_cpp_extrapolate(NOW, 0.25, args.repeats))
        rows["batch"][0].append(python_median(lambda: fs.predict_dead_reckoning_batch(*arrays, NOW), args.repeats))
        rows["batch"][1].append(fs._time_cpp_predict_dead_reckoning_batch(*arrays, NOW, args.repeats))
        rows["batch32"][0].append(python_median(lambda: fs.predict_dead_reckoning_batch(*single, NOW), args.repeats))
        rows["batch32"][1].append(fs._time_cpp_predict_dead_reckoning_batch(*single, NOW, args.repeats))

    print("%d entities, median of %d rounds of %d calls" % (args.entities, args.rounds, args.repeats))
    print("%-38s %12s %12s %8s" % ("call", "python (ms)", "C++ (ms)", "ratio"))
    names = {"soa": "DeadReckoningBatch.extrapolate", "batch": "predict_dead_reckoning_batch",
             "batch32": "predict_dead_reckoning_batch (f32)"}
    for key, (python_times, cpp_times) in rows.items():
        p, c = statistics.median(python_times) * 1e3, statistics.median(cpp_times) * 1e3
        print("%-38s %12.3f %12.3f %8.3f" % (names[key], p, c, p / c))


if __name__ == "__main__":
    main()
