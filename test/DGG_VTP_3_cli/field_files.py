#!/usr/bin/python3
# Checks a field file of dggvtp (PLY or VTK) against the mesh it was computed on and the text
# output of the same run: the header, the counts, the points, the faces (each the same cycle as
# the mesh file's), and the values bit for bit.
# usage: field_files.py ply|vtk FIELD MESH.ply DISTANCES.txt [LABELS.txt]
# With the environment variable FIELD_NAME (error_bound for --error-bounds), the values' name.
# Standard library only: the test must not depend on NumPy.
import math
import os
import struct
import sys

PLY_TYPES = {'char': 'b', 'uchar': 'B', 'short': 'h', 'ushort': 'H', 'int': 'i', 'uint': 'I',
             'float': 'f', 'double': 'd', 'int8': 'b', 'uint8': 'B', 'int16': 'h', 'uint16': 'H',
             'int32': 'i', 'uint32': 'I', 'float32': 'f', 'float64': 'd'}


def fail(message):
    sys.exit('field file check: ' + message)


def read_ply(path):
    """A binary little-endian PLY: (header lines, {element: [(properties...), ...]})."""
    data = open(path, 'rb').read()
    end = data.find(b'end_header\n')
    if not data.startswith(b'ply\n') or end < 0:
        fail(path + ': not a PLY file')
    header = data[:end].decode('ascii').split('\n')[:-1] + ['end_header']
    if header[1] != 'format binary_little_endian 1.0':
        fail(path + ': not binary little-endian: ' + header[1])
    elements = []
    for line in header:
        words = line.split()
        if words[0] == 'element':
            elements.append((words[1], int(words[2]), []))
        elif words[0] == 'property':
            elements[-1][2].append(words[1:])
    offset = end + len(b'end_header\n')
    result = {}
    for name, count, properties in elements:
        rows = []
        for _ in range(count):
            row = []
            for p in properties:
                if p[0] == 'list':
                    (n,) = struct.unpack_from('<' + PLY_TYPES[p[1]], data, offset)
                    offset += struct.calcsize(PLY_TYPES[p[1]])
                    item = '<%d%s' % (n, PLY_TYPES[p[2]])
                    row.append(list(struct.unpack_from(item, data, offset)))
                    offset += struct.calcsize(item)
                else:
                    (x,) = struct.unpack_from('<' + PLY_TYPES[p[0]], data, offset)
                    offset += struct.calcsize(PLY_TYPES[p[0]])
                    row.append(x)
            rows.append(row)
        result[name] = rows
    if offset != len(data):
        fail('%s: %d bytes after the last element' % (path, len(data) - offset))
    return header, result


def read_vtk(path):
    """Legacy binary VTK polydata: (points, faces, {scalar name: values})."""
    data = open(path, 'rb').read()
    offset = 0

    def line():
        nonlocal offset
        end = data.index(b'\n', offset)
        text = data[offset:end].decode('ascii')
        offset = end + 1
        return text

    def values(fmt, n):
        nonlocal offset
        item = '>%d%s' % (n, fmt)
        result = struct.unpack_from(item, data, offset)
        offset += struct.calcsize(item)
        if data[offset:offset + 1] != b'\n':
            fail(path + ': no newline after a binary block')
        offset += 1
        return result

    if line() != '# vtk DataFile Version 3.0':
        fail(path + ': not a legacy VTK file')
    line()  # the title
    if line() != 'BINARY' or line() != 'DATASET POLYDATA':
        fail(path + ': not binary polydata')
    words = line().split()
    if words[0] != 'POINTS' or words[2] != 'double':
        fail(path + ': POINTS line ' + ' '.join(words))
    n = int(words[1])
    flat = values('d', 3 * n)
    points = [flat[3 * i:3 * i + 3] for i in range(n)]
    words = line().split()
    if words[0] != 'POLYGONS':
        fail(path + ': POLYGONS line ' + ' '.join(words))
    flat = values('i', int(words[2]))
    faces, i = [], 0
    while i < len(flat):
        faces.append(list(flat[i + 1:i + 1 + flat[i]]))
        i += 1 + flat[i]
    if len(faces) != int(words[1]):
        fail(path + ': POLYGONS count')
    if line() != 'POINT_DATA %d' % n:
        fail(path + ': POINT_DATA line')
    scalars = {}
    while offset < len(data):
        words = line().split()
        if words[0] != 'SCALARS' or words[3] != '1' or line() != 'LOOKUP_TABLE default':
            fail(path + ': SCALARS lines ' + ' '.join(words))
        scalars[words[1]] = (words[2], values({'double': 'd', 'int': 'i'}[words[2]], n))
    return points, faces, scalars


def same_cycle(a, b):
    return len(a) == len(b) and any(a[k:] + a[:k] == b for k in range(len(a)))


def bits(x):
    return struct.pack('<d', x)


def main():
    kind, field, mesh_path, distances_path = sys.argv[1:5]
    name = os.environ.get('FIELD_NAME', 'distance')
    distances = [float(x) for x in open(distances_path).read().split()]
    labels = [int(x) for x in open(sys.argv[5]).read().split()] if len(sys.argv) > 5 else None
    _, mesh = read_ply(mesh_path)
    mesh_points = [row[:3] for row in mesh['vertex']]
    mesh_faces = [row[0] for row in mesh['face']]
    if len(distances) != len(mesh_points):
        fail('the text output is not one line per vertex')
    if kind == 'ply':
        header, elements = read_ply(field)
        expected = ['ply', 'format binary_little_endian 1.0', header[2],
                    'element vertex %d' % len(mesh_points), 'property float x', 'property float y',
                    'property float z', 'property float quality', 'property double ' + name] + \
                   (['property int label'] if labels else []) + \
                   ['element face %d' % len(mesh_faces), 'property list uchar int vertex_indices', 'end_header']
        if header != expected or not header[2].startswith('comment '):
            fail('PLY header:\n' + '\n'.join(header))
        rows = elements['vertex']
        points = [row[:3] for row in rows]
        faces = [row[0] for row in elements['face']]
        largest = max(struct.unpack('<f', struct.pack('<f', d))[0] for d in distances if math.isfinite(d))
        for row, d in zip(rows, distances):
            quality = struct.unpack('<f', struct.pack('<f', d if math.isfinite(d) else largest))[0]
            if bits(row[4]) != bits(d) or row[3] != quality:
                fail('PLY distance %r, quality %r for %r' % (row[4], row[3], d))
        if labels and [row[5] for row in rows] != labels:
            fail('PLY labels differ from the text output')
        # the mesh file's points are floats: read back exactly
        if points != mesh_points:
            fail('PLY points differ from the mesh file')
    else:
        points, faces, scalars = read_vtk(field)
        if list(scalars) != [name] + (['label'] if labels else []):
            fail('VTK scalars: %s' % list(scalars))
        if scalars[name][0] != 'double' or [bits(x) for x in scalars[name][1]] != [bits(d) for d in distances]:
            fail('VTK distances differ from the text output')
        if labels and (scalars['label'][0] != 'int' or list(scalars['label'][1]) != labels):
            fail('VTK labels differ from the text output')
        if [list(p) for p in points] != mesh_points:
            fail('VTK points differ from the mesh file')
    if len(faces) != len(mesh_faces) or not all(same_cycle(a, b) for a, b in zip(faces, mesh_faces)):
        fail('faces differ from the mesh file')


main()
