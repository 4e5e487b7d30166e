#!/usr/bin/env python3
"""The six outer faces of a Kerf colour volume (NRRD, `export-volume --quantity color`) as face images
A.png .. F.png in the faces' image orientation (Mokume's table, core/geometry/block.cpp Block::face), so
that ../shared/eval/appearance_eval.py can score a volume's surface against the photos as it scores
`render-faces`. Each face pixel is the volume sampled (trilinear, clamped to the outer voxel centres) at
the face point.

    python3 scripts/volume-faces.py VOLUME.nrrd OUT_DIR [--px 256]
"""
import argparse
import os
import sys

import cv2
import numpy as np


def read_nrrd(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"\n\n")
    fields = {}
    for line in data[:end].decode("ascii").splitlines()[1:]:
        if line.startswith("#") or ":=" in line or ": " not in line:
            continue
        key, value = line.split(": ", 1)
        fields[key] = value
    if fields.get("type") not in ("uchar", "unsigned char", "uint8") or fields.get("encoding") != "raw":
        sys.exit(f"volume-faces: {path} is not a raw uint8 colour volume")
    sizes = [int(v) for v in fields["sizes"].split()]  # 3 x y z
    volume = np.frombuffer(data[end + 2:], dtype=np.uint8).reshape(sizes[3], sizes[2], sizes[1], 3)
    dirs = fields["space directions"].replace("none", "").split(")")
    spacing = [float(d.strip(" (").split(",")[i]) for i, d in enumerate(dirs[:3])] if dirs else None
    return volume.astype(np.float32) / 255.0, np.array(spacing, dtype=np.float64)


def sample(volume, spacing, points):
    """Trilinear at block points (N x 3, mm), the block centred on the origin."""
    n = np.array([volume.shape[2], volume.shape[1], volume.shape[0]], dtype=np.float64)
    f = points / spacing + n / 2 - 0.5
    f = np.clip(f, 0, n - 1)
    a = np.minimum(np.floor(f).astype(int), np.maximum(n - 2, 0).astype(int))
    b = np.minimum(a + 1, (n - 1).astype(int))
    t = f - a
    out = np.zeros((points.shape[0], 3), dtype=np.float64)
    for corner in range(8):
        ix = b[:, 0] if corner & 1 else a[:, 0]
        iy = b[:, 1] if corner & 2 else a[:, 1]
        iz = b[:, 2] if corner & 4 else a[:, 2]
        w = (t[:, 0] if corner & 1 else 1 - t[:, 0]) * (t[:, 1] if corner & 2 else 1 - t[:, 1]) * \
            (t[:, 2] if corner & 4 else 1 - t[:, 2])
        out += w[:, None] * volume[iz, iy, ix]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("volume")
    parser.add_argument("out")
    parser.add_argument("--px", type=int, default=256, help="pixels along a face's width")
    args = parser.parse_args()
    volume, spacing = read_nrrd(args.volume)
    size = spacing * np.array([volume.shape[2], volume.shape[1], volume.shape[0]])
    h = size / 2
    X, Y, Z = np.eye(3)
    # centre, right, down, width, height (Block::face)
    faces = {
        "A": (Z * h[2], X, -Y, size[0], size[1]),
        "B": (Y * h[1], X, Z, size[0], size[2]),
        "C": (-X * h[0], Z, -Y, size[2], size[1]),
        "D": (-Y * h[1], X, -Z, size[0], size[2]),
        "E": (X * h[0], -Z, -Y, size[2], size[1]),
        "F": (-Z * h[2], -X, -Y, size[0], size[1]),
    }
    os.makedirs(args.out, exist_ok=True)
    for name, (centre, right, down, width, height) in faces.items():
        w = args.px
        hpx = max(1, int(round(w * height / width)))
        u = ((np.arange(w) + 0.5) / w - 0.5) * width
        v = ((np.arange(hpx) + 0.5) / hpx - 0.5) * height
        uu, vv = np.meshgrid(u, v)
        points = centre[None, :] + uu.reshape(-1, 1) * right[None, :] + vv.reshape(-1, 1) * down[None, :]
        rgb = sample(volume, spacing, points).reshape(hpx, w, 3)
        cv2.imwrite(os.path.join(args.out, name + ".png"),
                    cv2.cvtColor((np.clip(rgb, 0, 1) * 255 + 0.5).astype(np.uint8), cv2.COLOR_RGB2BGR))


if __name__ == "__main__":
    main()
