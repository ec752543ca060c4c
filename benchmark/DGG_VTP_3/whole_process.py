#!/usr/bin/env python3
"""The whole process of dggvtp, stage by stage, on 1 and more threads (issue 37).

Runs `dggvtp MESH --epsilon E --threads T --output FILE --stats FILE` for each thread count in
turn, --repeat rounds alternating the thread counts (the machine's noise then falls on all of them
alike), and reports per thread count the median of each stage of --stats (load, repair, prepare,
locate, propagate, write) and of the process's wall time (measured here, from the start of the
process to its exit: it includes what no stage counts, such as freeing the memory), with

- the preparation's speed-up over 1 thread (ratio of the medians),
- the wall time over the propagation's time, per thread count,
- each stage's share of the wall time,
- an Amdahl projection to --project cores: the parallel fraction f of the preparation and of the
  propagation from their speed-up S on T threads (f = (1 - 1/S) / (1 - 1/T)), the other stages
  and the rest of the wall time serial, T(P) = T(1) ((1 - f) + f / P);
- whether the output is the same bytes for every thread count (it must be).

On a shared machine, --wait-idle makes each run wait (at most that many seconds) until no other
task is runnable (/proc/loadavg), three samples 0.2 s apart; a run that gave up waiting is marked.

Example (from the repository root, after building dggvtp in build/; the mesh from
benchmark/DGG_VTP_3/make_large.sh /tmp/large_meshes bunny_1M):
  python3 benchmark/DGG_VTP_3/whole_process.py --mesh /tmp/large_meshes/bunny_1M.ply --epsilon 1e-2 --repeat 5
"""
import argparse
import filecmp
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STAGES = ['load', 'repair', 'prepare', 'locate', 'propagate', 'write']
PARALLEL = ['prepare', 'propagate']


def wait_idle(limit):
    """True once no other task has been runnable for three samples in a row, False after `limit` s."""
    quiet, start = 0, time.monotonic()
    while time.monotonic() - start < limit:
        with open('/proc/loadavg') as f:
            running = int(f.read().split()[3].split('/')[0])
        quiet = quiet + 1 if running <= 1 else 0
        if quiet == 3:
            return True
        time.sleep(0.2)
    return False


def amdahl_fraction(speed_up, threads):
    return max(0., min(1., (1. - 1. / speed_up) / (1. - 1. / threads)))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--mesh', required=True)
    parser.add_argument('--dggvtp', default=os.path.join(REPO, 'build', 'bin', 'dggvtp'))
    parser.add_argument('--epsilon', default='1e-2')
    parser.add_argument('--source', type=int, default=0)
    parser.add_argument('--threads', default='1,2', help='comma-separated thread counts, 1 first')
    parser.add_argument('--repeat', type=int, default=3)
    parser.add_argument('--project', type=int, default=16, help='cores of the Amdahl projection')
    parser.add_argument('--extra', default='', help='more dggvtp options, space-separated (e.g. --max-distance 0)')
    parser.add_argument('--wait-idle', type=float, default=0., help='seconds to wait for an idle machine before a run')
    args = parser.parse_args()
    threads = [int(t) for t in args.threads.split(',')]
    if threads[0] != 1 or len(threads) < 2 or args.repeat < 1:
        sys.exit('error: --threads must start with 1 and name another count; --repeat at least 1')

    runs = {t: [] for t in threads}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.repeat):
            for t in threads:
                out, st = os.path.join(tmp, 'd%d.txt' % t), os.path.join(tmp, 's.json')
                command = [args.dggvtp, args.mesh, '--quiet', '--source', str(args.source), '--epsilon', args.epsilon,
                           '--threads', str(t), '--output', out, '--stats', st] + args.extra.split()
                idle = wait_idle(args.wait_idle) if args.wait_idle > 0 else None
                start = time.perf_counter()
                done = subprocess.run(command, stderr=subprocess.PIPE, text=True)
                wall = time.perf_counter() - start
                if done.returncode != 0:
                    sys.exit('error: dggvtp failed: %s' % done.stderr)
                with open(st) as f:
                    stats = json.load(f)
                row = {s: stats['seconds_' + s] for s in STAGES}
                row['wall'] = wall
                row['per_stage'] = stats['threads_per_stage']
                runs[t].append(row)
                print('%d threads, run %d: wall %.3f s, %s%s' % (t, r + 1, wall, ', '.join(
                    '%s %.3f' % (s, row[s]) for s in STAGES), ' (machine busy)' if idle is False else ''),
                      file=sys.stderr, flush=True)
            same = all(filecmp.cmp(os.path.join(tmp, 'd1.txt'), os.path.join(tmp, 'd%d.txt' % t), shallow=False)
                       for t in threads[1:])
            if not same:
                sys.exit('error: the output differs between thread counts')

    median = {t: {k: statistics.median(run[k] for run in runs[t]) for k in STAGES + ['wall']} for t in threads}
    print('%s, epsilon %s, source %d, %d runs per thread count (alternating), medians; the output the same '
          'bytes for every thread count\n' % (os.path.basename(args.mesh), args.epsilon, args.source, args.repeat))
    print('| threads | wall (s) | ' + ' | '.join('%s (s)' % s for s in STAGES) + ' | wall / propagate | load + write share |')
    print('|---:|---:|' + '---:|' * len(STAGES) + '---:|---:|')
    for t in threads:
        m = median[t]
        print('| %d | %.3f | %s | %.2f | %.1f%% |' % (t, m['wall'], ' | '.join('%.3f' % m[s] for s in STAGES),
                                                     m['wall'] / m['propagate'], 100. * (m['load'] + m['write']) / m['wall']))
    print('\nthreads per stage: ' + '; '.join('%d: %s' % (t, runs[t][0]['per_stage']) for t in threads))
    print('runs (wall s): ' + '; '.join('%d: %s' % (t, ' '.join('%.3f' % r['wall'] for r in runs[t])) for t in threads))
    print('runs (prepare s): ' + '; '.join('%d: %s' % (t, ' '.join('%.3f' % r['prepare'] for r in runs[t]))
                                          for t in threads))
    one, many = median[1], median[threads[-1]]
    t = threads[-1]
    print('\npreparation: %.3f s on 1 thread, %.3f s on %d: %.2fx' % (one['prepare'], many['prepare'], t,
                                                                     one['prepare'] / many['prepare']))
    # Amdahl, from 1 and t threads
    # the serial part as measured in the parallel runs (the same work on 1 thread, within the noise)
    serial = many['wall'] - sum(many[s] for s in PARALLEL)
    print('serial rest (wall - prepare - propagate): %.3f s on 1 thread, %.3f s on %d'
          % (one['wall'] - sum(one[s] for s in PARALLEL), serial, t))
    projected = {}
    for s in PARALLEL:
        f = amdahl_fraction(one[s] / many[s], t)
        projected[s] = one[s] * ((1. - f) + f / args.project)
        print('%s: speed-up %.2fx on %d threads, parallel fraction %.3f, projected %.3f s on %d cores'
              % (s, one[s] / many[s], t, f, projected[s], args.project))
    whole = serial + sum(projected.values())
    print('projected whole process on %d cores %.3f s, %.2f x its propagation'
          % (args.project, whole, whole / projected['propagate']))


if __name__ == '__main__':
    main()
