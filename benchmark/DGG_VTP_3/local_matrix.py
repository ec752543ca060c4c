"""Local distance matrices (issue 36): the Python module's local_distance_matrix() and
dggvtp-batch --max-distance on a 163,842-vertex mesh (the icosphere of fsaverage's size, the
cortical surfaces gdist's local_gdist_matrix is used on), with a radius of about 100 neighbours
per vertex: time, peak memory, entries; every row against distances(s, max_distance=D); the two
against each other; and the dense paths (distances_from_each) for comparison. Prints Table 11.

usage: PYTHONPATH=build/python /usr/bin/python3 benchmark/DGG_VTP_3/local_matrix.py
           [--batch build/bin/dggvtp-batch] [--mesh FILE | --icosphere LEVEL] [--neighbours 100]
           [--threads 2] [--check all|K] [--dense-rows 400] [--full-rows 8] [--fixed-cost K]
           [--levels 5,6,7 [--gdist]]
Each measurement runs in a process of its own (peak RSS: ru_maxrss of that process); the mesh is
generated (level 7: 163,842 vertices, unit sphere) into a temporary directory, never stored.
--fixed-cost K measures only what a row costs whatever its radius: K rows (spread over the mesh) at
max_distance 0 and at D, alternated 3 times in one process, one thread.
--levels L1,L2,...: the side-by-side of issue 42 (Table 11): per icosphere level, the whole matrix
by local_distance_matrix on one thread (exact), on --threads threads (exact) and on one thread at
accuracy 1e-3, each in a process of its own; with --gdist, also gdist's local_gdist_matrix on one
thread when `import gdist` works (tvb-gdist, a benchmark peer built outside the repository: see
the benchmark README), and the largest difference of its entries from ours."""
import argparse
import json
import math
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np


def icosphere(level):
    """the icosahedron's faces cut in 4, `level` times, on the unit sphere (as fsaverage's
    sphere: 10 * 4**level + 2 vertices)"""
    t = (1 + 5 ** 0.5) / 2
    V = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
                  [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]], dtype=float)
    F = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
                  [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5],
                  [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]])
    for _ in range(level):
        edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
        unique, inverse = np.unique(edges, axis=0, return_inverse=True)
        mid = len(V) + inverse.reshape(3, -1)  # the new vertex of edges 01, 12, 20 of each face
        V = np.concatenate([V, (V[unique[:, 0]] + V[unique[:, 1]]) / 2])
        a, b, c = F.T
        F = np.concatenate([np.column_stack([a, mid[0], mid[2]]), np.column_stack([b, mid[1], mid[0]]),
                            np.column_stack([c, mid[2], mid[1]]), np.column_stack([mid[0], mid[1], mid[2]])])
    return V / np.linalg.norm(V, axis=1)[:, None], F


def write_ply(path, V, F):
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(V)}\nproperty double x\nproperty double y\n"
              f"property double z\nelement face {len(F)}\nproperty list uchar int vertex_indices\nend_header\n")
    faces = np.zeros(len(F), dtype=[("n", "u1"), ("i", "<i4", 3)])
    faces["n"], faces["i"] = 3, F
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(V.astype("<f8").tobytes())
        f.write(faces.tobytes())


def peak_mb():
    """this process's peak RSS: VmHWM, of its own memory; not ru_maxrss, which Linux carries over
    from the parent through fork and exec (a child of a large process would report that one)"""
    for line in open("/proc/self/status"):
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024
    raise RuntimeError("no VmHWM in /proc/self/status")


def child(args):
    """one measurement in this process; prints a JSON line"""
    import dggvtp
    import scipy.sparse
    V, F = dggvtp.read_mesh(args.mesh)
    solver = dggvtp.GeodesicSolver(V, F)
    out = {"prepared_mb": peak_mb()}
    t0 = time.perf_counter()
    if args.child == "fixed":
        rows = np.arange(args.rows) * (len(V) // args.rows)
        times = {0.0: [], args.max_distance: []}
        for _ in range(3):
            for D in times:
                t0 = time.perf_counter()
                solver.local_distance_matrix(D, rows, threads=1)
                times[D].append(time.perf_counter() - t0)
        out["rows"] = len(rows)
        out["ms_per_row_at_0"] = statistics.median(times[0.0]) / len(rows) * 1e3
        out["ms_per_row_at_D"] = statistics.median(times[args.max_distance]) / len(rows) * 1e3
    elif args.child == "gdist":
        import gdist
        M = gdist.local_gdist_matrix(np.ascontiguousarray(V, dtype=np.float64),
                                     np.ascontiguousarray(F, dtype=np.int32), max_distance=args.max_distance)
        out["seconds"] = time.perf_counter() - t0
        out["nnz"] = int(M.nnz)
        scipy.sparse.save_npz(args.save, M.tocsr(), compressed=False)
    elif args.child == "sparse":
        M = solver.local_distance_matrix(args.max_distance, threads=args.threads, epsilon=args.epsilon)
        out["seconds"] = time.perf_counter() - t0
        out["nnz"] = int(M.nnz)
        out["matrix_mb"] = (M.data.nbytes + M.indices.nbytes + M.indptr.nbytes) / 2**20
        scipy.sparse.save_npz(args.save, M, compressed=False)
    else:  # dense rows, cut at max_distance (--child dense) or whole (--child full)
        rows = np.arange(args.rows) * (len(V) // args.rows)
        D = solver.distances_from_each(rows, max_distance=args.max_distance if args.child == "dense" else math.inf,
                                       threads=args.threads)
        out["seconds"] = time.perf_counter() - t0
        out["rows"] = len(rows)
        out["array_mb"] = D.nbytes / 2**20
    out["peak_mb"] = peak_mb()
    print(json.dumps(out))


def measure(args, kind, **extra):
    command = [sys.executable, __file__, "--child", kind, "--mesh", args.mesh, "--threads", str(args.threads),
               "--max-distance", repr(args.max_distance), "--epsilon", repr(args.epsilon)]
    for k, v in extra.items():
        command += [f"--{k}", str(v)]
    result = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(result.stdout.strip().split("\n")[-1])


def check_rows(mesh, M, D, rows, threads):
    """every row of `rows` as an array (inf where no entry) against distances(s, max_distance=D), bit
    for bit, from `threads` Python threads; returns the rows that differ"""
    import dggvtp
    solver = dggvtp.GeodesicSolver(*dggvtp.read_mesh(mesh))
    bad = []

    def work(part):
        for k in part:
            row = np.full(M.shape[1], np.inf)
            row[M.indices[M.indptr[k]:M.indptr[k + 1]]] = M.data[M.indptr[k]:M.indptr[k + 1]]
            if row.tobytes() != solver.distances(int(k), max_distance=D).tobytes():
                bad.append(int(k))
    workers = [threading.Thread(target=work, args=(rows[i::threads],)) for i in range(threads)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    return bad


def levels(args):
    """Table 11 of issue 42: per level, the whole matrix by each path, one process each"""
    import copy
    import scipy.sparse
    rows = []
    for level in [int(x) for x in args.levels.split(",")]:
        with tempfile.TemporaryDirectory() as tmp:
            tmp = pathlib.Path(tmp)
            a = copy.copy(args)
            a.mesh = str(tmp / f"icosphere_{level}.ply")
            V, F = icosphere(level)
            write_ply(a.mesh, V, F)
            area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()
            a.max_distance = math.sqrt(args.neighbours * area / len(V) / math.pi)
            row = {"level": level, "vertices": len(V), "D": a.max_distance}
            for name, threads, epsilon in (("one", 1, 0.), ("threads", args.threads, 0.), ("eps", 1, 1e-3)):
                a.threads, a.epsilon = threads, epsilon
                row[name] = measure(a, "sparse", save=tmp / f"{name}.npz")
                print(f"level {level}, {name}: {row[name]}", flush=True)
            ours = scipy.sparse.load_npz(tmp / "one.npz")
            row["entries"] = ours.nnz
            if args.gdist:
                try:
                    import gdist  # noqa: F401
                except ImportError:
                    print("gdist is not importable: its column is left empty", flush=True)
                else:
                    a.threads, a.epsilon = 1, 0.
                    row["gdist"] = measure(a, "gdist", save=tmp / "gdist.npz")
                    G = scipy.sparse.load_npz(tmp / "gdist.npz")
                    # gdist stores no zero on the diagonal: compare the off-diagonal entries
                    ours_off = ours - scipy.sparse.diags(ours.diagonal())
                    ours_off.eliminate_zeros()
                    row["gdist_max_difference"] = float(abs(G - ours_off).max())
                    row["gdist_entries"] = G.nnz
                    print(f"level {level}, gdist: {row['gdist']}, largest difference {row['gdist_max_difference']:.3g}",
                          flush=True)
            rows.append(row)
    print(f"\n| level | vertices | D | entries a row | gdist, 1 thread | ours, 1 thread | gdist / ours | ours, "
          f"{args.threads} threads | ours, 1e-3, 1 thread | per row, 1 thread |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        g = r.get("gdist")
        gdist_time = f"{g['seconds']:.2f} s" if g else "not run"
        ratio = f"{g['seconds'] / r['one']['seconds']:.1f}" if g else ""
        print(f"| {r['level']} | {r['vertices']:,} | {r['D']:.6g} | {r['entries'] / r['vertices']:.1f} | "
              f"{gdist_time} | {r['one']['seconds']:.2f} s | {ratio} | {r['threads']['seconds']:.2f} s | "
              f"{r['eps']['seconds']:.2f} s | {r['one']['seconds'] / r['vertices'] * 1e3:.3f} ms |")
    print("\npeak RSS (MB) of local_distance_matrix, 1 thread, and of its result: " +
          ", ".join(f"level {r['level']}: {r['one']['peak_mb']:.0f} ({r['one']['prepared_mb']:.0f} prepared, "
                    f"matrix {r['one']['matrix_mb']:.0f})" for r in rows))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--batch", default=str(pathlib.Path(__file__).resolve().parents[2] / "build" / "bin" / "dggvtp-batch"))
    parser.add_argument("--mesh")
    parser.add_argument("--icosphere", type=int, default=7)
    parser.add_argument("--neighbours", type=float, default=100)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--check", default="all")
    parser.add_argument("--dense-rows", type=int, default=400)
    parser.add_argument("--full-rows", type=int, default=8)
    parser.add_argument("--fixed-cost", type=int)
    parser.add_argument("--child")
    parser.add_argument("--max-distance", type=float)
    parser.add_argument("--save")
    parser.add_argument("--rows", type=int)
    parser.add_argument("--epsilon", type=float, default=0.)
    parser.add_argument("--levels")
    parser.add_argument("--gdist", action="store_true")
    args = parser.parse_args()
    if args.child:
        return child(args)

    import dggvtp
    import scipy.sparse
    if args.levels:
        return levels(args)
    if args.fixed_cost:
        args.threads = 1
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        if not args.mesh:
            args.mesh = str(tmp / f"icosphere_{args.icosphere}.ply")
            write_ply(args.mesh, *icosphere(args.icosphere))
        V, F = dggvtp.read_mesh(args.mesh)
        n = len(V)
        area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()
        args.max_distance = math.sqrt(args.neighbours * area / n / math.pi)  # the disc of that many vertices' area
        load = os.getloadavg()
        print(f"{pathlib.Path(args.mesh).name}: {n} vertices, {len(F)} faces; max_distance {args.max_distance:.6g} "
              f"(about {args.neighbours:g} neighbours); {args.threads} threads; load average before {load[0]:.2f}",
              flush=True)
        if args.fixed_cost:
            fixed = measure(args, "fixed", rows=args.fixed_cost)
            load_after = os.getloadavg()
            print(f"{fixed['rows']} rows, one thread, median of 3: {fixed['ms_per_row_at_0']:.2f} ms a row at "
                  f"max_distance 0, {fixed['ms_per_row_at_D']:.2f} ms at {args.max_distance:.6g}; load average after "
                  f"{load_after[0]:.2f}")
            return

        sparse = measure(args, "sparse", save=tmp / "python.npz")
        M = scipy.sparse.load_npz(tmp / "python.npz")
        print(f"local_distance_matrix: {sparse}", flush=True)

        stats = tmp / "stats.json"
        t0 = time.perf_counter()
        # through a shell that forks it: its --stats peak (ru_maxrss) is then its own, not this process's
        subprocess.run(["sh", "-c", '"$@"; exit $?', "sh", args.batch, args.mesh, "--sources", "all", "--max-distance",
                        repr(args.max_distance), "--output", tmp / "batch.npz", "--threads", str(args.threads),
                        "--stats", stats, "--quiet"], check=True)
        batch_seconds = time.perf_counter() - t0
        batch = json.loads(stats.read_text())
        B = scipy.sparse.load_npz(tmp / "batch.npz")
        same = all(getattr(B, a).tobytes() == getattr(M, a).tobytes() for a in ("data", "indices", "indptr"))
        print(f"dggvtp-batch: {batch_seconds:.1f} s, rows {batch['seconds_compute']:.1f} s, peak RSS "
              f"{batch['peak_rss_mb']} MB, the same matrix: {same}", flush=True)

        rows = np.arange(n) if args.check == "all" else np.linspace(0, n - 1, int(args.check)).astype(int)
        t0 = time.perf_counter()
        bad = check_rows(args.mesh, M, args.max_distance, rows, args.threads)
        print(f"rows checked against distances(s, max_distance=D): {len(rows)} in {time.perf_counter() - t0:.0f} s, "
              f"{len(bad)} differ {bad[:10]}", flush=True)

        dense = measure(args, "dense", rows=args.dense_rows)
        full = measure(args, "full", rows=args.full_rows)
        print(f"distances_from_each, max_distance: {dense}\ndistances_from_each, whole rows: {full}", flush=True)
        load_after = os.getloadavg()

    per_row = lambda r: r["seconds"] / r["rows"]
    rows_n = n
    print(f"\nload average before {load[0]:.2f}, after {load_after[0]:.2f}\n")
    print("| path | rows | time | per row | peak RSS | result |")
    print("|---|---:|---:|---:|---:|---|")
    print(f"| `local_distance_matrix(D, threads={args.threads})` | {n:,} | {sparse['seconds']:.1f} s | "
          f"{sparse['seconds'] / n * 1e3:.2f} ms | {sparse['peak_mb']:.0f} MB ({sparse['prepared_mb']:.0f} MB after "
          f"preparing) | CSR, {sparse['nnz']:,} entries ({sparse['nnz'] / n:.1f} a row), {sparse['matrix_mb']:.0f} MB |")
    print(f"| `dggvtp-batch --max-distance D --threads {args.threads}` | {n:,} | {batch['seconds_compute']:.1f} s "
          f"(command {batch_seconds:.1f} s) | {batch['seconds_compute'] / n * 1e3:.2f} ms | {batch['peak_rss_mb'][0]:.0f} MB "
          f"| .npz: the same arrays: {same} |")
    print(f"| `distances_from_each(rows, max_distance=D, threads={args.threads})` | {dense['rows']} | "
          f"{dense['seconds']:.1f} s | {per_row(dense) * 1e3:.2f} ms | {dense['peak_mb']:.0f} MB | dense "
          f"({dense['array_mb']:.0f} MB); all {n:,} rows: {n * n * 8 / 1e9:.0f} GB, {per_row(dense) * n:.0f} s |")
    print(f"| `distances_from_each(rows, threads={args.threads})` (whole rows) | {full['rows']} | {full['seconds']:.1f} s | "
          f"{per_row(full) * 1e3:.0f} ms | {full['peak_mb']:.0f} MB | dense; all {n:,} rows: {n * n * 8 / 1e9:.0f} GB, "
          f"{per_row(full) * n / 3600:.1f} h |")
    print(f"\nEvery row checked: {len(rows):,} of {n:,}, {len(bad)} differ from distances(s, max_distance=D) "
          f"(bit for bit); dggvtp-batch's .npz holds the same arrays: {same}.")


if __name__ == "__main__":
    main()
