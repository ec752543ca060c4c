"""Early termination at accuracies where windows stop (issue 43, item 2): targets and max_distance
against the full field and the exact one, every vertex of pinion as a target (and of spot from one
source). A stopped window's relay can emit again at a distance below the limit
(internal/early_termination.h): the values must stay within the contract, a vertex beyond
max_distance must be one whose full-field distance is beyond it, and the values of interest are
the full field's bit for bit."""
import numpy as np
import pytest

import dggvtp
from conftest import mesh


@pytest.mark.parametrize("name, sources", [("pinion.ply", [0, 307, 332]), ("spot.ply", [1386])])
def test_targets_and_max_distance_where_windows_stop(name, sources):
    V, F = dggvtp.read_mesh(mesh(name))
    solver = dggvtp.GeodesicSolver(V, F)
    n = len(V)
    different = checked = 0
    for source in sources:
        exact = solver.distances(source)
        for epsilon in (1.0, 0.5) if n < 1000 else (1.0,):   # epsilon sqrt(n) >= 10: windows stop
            full = solver.distances(source, epsilon=epsilon)
            targets = np.array([solver.target_distances(source, t, epsilon=epsilon)[0] for t in range(n)])
            assert np.all(targets >= exact * (1 - 1e-12)) and np.all(targets <= exact * (1 + epsilon))
            different += np.count_nonzero(targets.view(np.uint64) != full.view(np.uint64))
            checked += n
            for radius in np.quantile(exact, [0.1, 0.5, 0.9]):
                d = solver.distances(source, epsilon=epsilon, max_distance=radius)
                kept = np.isfinite(d)
                assert np.all(d[kept] <= radius)
                assert np.all(d[kept] >= exact[kept] * (1 - 1e-12)) and np.all(d[kept] <= exact[kept] * (1 + epsilon))
                assert not np.any(~kept & (full <= radius)), "a vertex within the radius in the full field is lost"
                assert np.all(kept[exact * (1 + epsilon) <= radius])
                different += np.count_nonzero(d[kept].view(np.uint64) != full[kept].view(np.uint64))
                checked += np.count_nonzero(kept)
    assert different == 0, f"{name}: {different} of {checked} distances of interest differ from the full field's bits"
