"""The exact mode against CGAL's Surface_mesh_shortest_path on generated meshes where it once missed
paths: a straight path through several vertices of a grid wrapped around a bore (coupling, source
1447: vertex 786 0.48% too long) or along a terrace (terrain_cliffs, source 836: vertex 2157 0.87%).
Both ends of each pair are sources, every vertex compared within 1e-9 relative.

usage: exact_against_smsp.py BUILD MESH_FOLDER   (the folder of hard_meshes.py's full-size meshes)
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

CASES = {'coupling': (1447, 786), 'terrain_cliffs': (836, 2157)}


def distances(command, out):
    subprocess.run(command, check=True)
    return np.loadtxt(out)


def main():
    build, folder = sys.argv[1:3]
    failed = False
    with tempfile.TemporaryDirectory() as tmp:
        for name, pair in CASES.items():
            mesh = os.path.join(folder, name + '.ply')
            for source in pair:
                ours = distances([os.path.join(build, 'bin', 'dggvtp'), mesh, '--source', str(source), '--exact',
                                  '--output', os.path.join(tmp, 'ours.txt'), '--quiet'], os.path.join(tmp, 'ours.txt'))
                smsp = distances([os.path.join(build, 'bin', 'smsp_distances'), mesh, str(source),
                                  os.path.join(tmp, 'smsp.txt'), os.path.join(tmp, 'smsp.json')], os.path.join(tmp, 'smsp.txt'))
                reached = smsp > 0
                error = np.abs(ours[reached] - smsp[reached]) / smsp[reached]
                worst = int(np.flatnonzero(reached)[np.argmax(error)])
                print(f'{name}, source {source}: largest relative difference {error.max():.3g} at vertex {worst} '
                      f'({ours[worst]!r} against {smsp[worst]!r})')
                failed |= not bool(error.max() <= 1e-9) or ours[source] != 0.  # a NaN fails
    sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
