#!/usr/bin/env python3
"""Small PLY helpers for scripts/screenshots.sh (binary little-endian PLY, float vertex
properties only, as the owl sample, the shared scans and MeshLab's output are).

  screenshot_data.py outliers IN.ply OUT.ply COUNT     IN plus COUNT random points around it
  screenshot_data.py subsample IN.ply OUT.ply STEP     every STEP-th vertex of IN
  screenshot_data.py side_by_side OUT.mlp A.ply B.ply ...   a MeshLab project with the meshes
                                                       side by side along x (one view, one light)
"""
import random
import struct
import sys


def read(path):
    """(header text, vertex count, bytes per vertex, body bytes) of a PLY file."""
    data = open(path, 'rb').read()
    body = data.index(b'end_header\n') + 11
    head = data[:body].decode()
    count = int(head.split('element vertex ')[1].split()[0])
    vertex_part = head.split('element vertex')[1].split('element')[0]
    return head, count, 4 * vertex_part.count('property float'), data[body:]


def points(path):
    head, count, stride, body = read(path)
    return [struct.unpack_from('<3f', body, stride * i) for i in range(count)]


def outliers(src, dst, count):
    pts = points(src)
    lo = [min(p[a] for p in pts) for a in range(3)]
    hi = [max(p[a] for p in pts) for a in range(3)]
    random.seed(5)
    extra = [[lo[a] + (hi[a] - lo[a]) * (1.2 * random.random() - 0.1) for a in range(3)]
             for _ in range(count)]
    head = ('ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n'
            'property float y\nproperty float z\nend_header\n' % (len(pts) + count))
    with open(dst, 'wb') as out:
        out.write(head.encode())
        out.write(b''.join(struct.pack('<3f', *p) for p in pts + extra))


def subsample(src, dst, step):
    head, count, stride, body = read(src)
    if 'element face' in head:
        raise SystemExit('subsample: %s has faces' % src)
    kept = range(0, count, step)
    head = head.replace('element vertex %d' % count, 'element vertex %d' % len(kept))
    with open(dst, 'wb') as out:
        out.write(head.split('end_header\n')[0].encode() + b'end_header\n')
        out.write(b''.join(body[stride * i:stride * (i + 1)] for i in kept))


def side_by_side(dst, meshes):
    ranges = []
    for mesh in meshes:
        xs = [p[0] for p in points(mesh)]
        ranges.append((min(xs), max(xs)))
    step = 1.1 * max(hi - lo for lo, hi in ranges)
    layers = ''.join(
        ' <MLMesh label="%s" filename="%s" visible="1">\n  <MLMatrix44>\n'
        '1 0 0 %g \n0 1 0 0 \n0 0 1 0 \n0 0 0 1 \n</MLMatrix44>\n </MLMesh>\n'
        % (mesh.rsplit('/', 1)[-1][:-4], mesh, k * step) for k, mesh in enumerate(meshes))
    with open(dst, 'w') as out:
        out.write('<!DOCTYPE MeshLabDocument>\n<MeshLabProject>\n <MeshGroup>\n' + layers +
                  ' </MeshGroup>\n <RasterGroup/>\n</MeshLabProject>\n')


if __name__ == '__main__':
    command, args = sys.argv[1], sys.argv[2:]
    if command == 'outliers':
        outliers(args[0], args[1], int(args[2]))
    elif command == 'subsample':
        subsample(args[0], args[1], int(args[2]))
    elif command == 'side_by_side':
        side_by_side(args[0], args[1:])
    else:
        raise SystemExit(__doc__)
