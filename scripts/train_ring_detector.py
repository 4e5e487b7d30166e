#!/usr/bin/env python3
"""Trains Kerf's learned ring detector (issue 18 item 1; docs/rings.md "The learned detector").

A small fully-convolutional network (a U-Net of three levels) learns the ring-localization image of
Mokume Eq. 1 from faces rendered by Kerf's own model (bench/ring_training_data.cpp), as the
learned-inference paper trains on procedural data. No real photo is used: CN03's U-Net maps serve only to
validate afterwards (tests/core/test_learned_ring_detector.cpp).

Domain randomisation on top of the rendered faces (each crop draws its own): scale, rotation by 90 degrees
and mirroring, white balance, exposure, gamma, contrast, grey photos, blur, sensor noise, JPEG, saw marks,
sanding scratches, uneven light.

Usage (Debian packages python3-torch python3-opencv python3-numpy: scripts/install-deps.sh --training):
  build/test/bench/kerf_ring_training_data DATA 400 1000
  python3 scripts/train_ring_detector.py DATA [DATA2 ..] resources/models/ring_detector.onnx [--minutes 20]

The network's input is the photo resampled to 6.4 px/mm (Mokume's 256 px per 40 mm), RGB in 0..1, each
channel minus its mean over the image, all divided by the image's standard deviation (the same in
core/rings/learned_ring_detector.cpp). Its output is Eq. 1's ring-localization image, 0..1. Deterministic
for a seed on one thread count.
"""
import argparse
import glob
import math
import os
import sys
import time

import cv2
import numpy as np
import torch
import torch.nn as nn
import torch.nn.functional as F

CROP = 128


def block(cin, cout, dilation=1):
    return nn.Sequential(
        nn.Conv2d(cin, cout, 3, padding=dilation, dilation=dilation, bias=False), nn.BatchNorm2d(cout),
        nn.ReLU(inplace=True),
        nn.Conv2d(cout, cout, 3, padding=dilation, dilation=dilation, bias=False), nn.BatchNorm2d(cout),
        nn.ReLU(inplace=True))


class RingNet(nn.Module):
    """Three levels down (1/8 resolution, receptive field about 15 mm at 6.4 px/mm), skips, one output."""

    def __init__(self, w=16):
        super().__init__()
        self.e1 = block(3, w)
        self.e2 = block(w, 2 * w)
        self.e3 = block(2 * w, 4 * w)
        self.mid = block(4 * w, 4 * w, dilation=2)
        self.u3 = nn.ConvTranspose2d(4 * w, 4 * w, 2, stride=2)
        self.d3 = block(8 * w, 2 * w)
        self.u2 = nn.ConvTranspose2d(2 * w, 2 * w, 2, stride=2)
        self.d2 = block(4 * w, w)
        self.u1 = nn.ConvTranspose2d(w, w, 2, stride=2)
        self.d1 = block(2 * w, w)
        self.out = nn.Conv2d(w, 1, 1)

    def forward(self, x):
        e1 = self.e1(x)
        e2 = self.e2(F.max_pool2d(e1, 2))
        e3 = self.e3(F.max_pool2d(e2, 2))
        m = self.mid(F.max_pool2d(e3, 2))
        d3 = self.d3(torch.cat([self.u3(m), e3], 1))
        d2 = self.d2(torch.cat([self.u2(d3), e2], 1))
        d1 = self.d1(torch.cat([self.u1(d2), e1], 1))
        return self.out(d1)


class Exported(nn.Module):
    """What ships: the probability, not the logit."""

    def __init__(self, net):
        super().__init__()
        self.net = net

    def forward(self, x):
        return torch.sigmoid(self.net(x))


def normalise(rgb):
    """rgb: H x W x 3 float32 in 0..1 -> 3 x H x W, as the C++ side does."""
    x = rgb - rgb.reshape(-1, 3).mean(0)
    x = x / (x.std() + 1e-3)
    return np.ascontiguousarray(x.transpose(2, 0, 1))


def load(folder):
    stems = sorted(os.path.basename(p)[:-10] for p in glob.glob(os.path.join(folder, "*_photo.png")))
    if not stems:
        sys.exit(f"error: no *_photo.png in {folder} (run kerf_ring_training_data first)")
    photos, arls = [], []
    for s in stems:
        p = cv2.imread(os.path.join(folder, s + "_photo.png"), cv2.IMREAD_COLOR)
        a = cv2.imread(os.path.join(folder, s + "_arl.png"), cv2.IMREAD_GRAYSCALE)
        if p is None or a is None or p.shape[:2] != a.shape:
            sys.exit(f"error: {s}: photo or ring image missing or of another size")
        photos.append(p[:, :, ::-1].copy())  # RGB
        arls.append(a)
    return stems, photos, arls


def augment(photo, arl, rng):
    """One training crop (CROP x CROP) with the photo's conditions randomised."""
    scale = math.exp(rng.uniform(math.log(0.85), math.log(1.18)))
    h, w = arl.shape
    side = int(math.ceil(CROP / scale)) + 2
    side = min(side, h, w)
    y0, x0 = rng.integers(0, h - side + 1), rng.integers(0, w - side + 1)
    p = photo[y0:y0 + side, x0:x0 + side].astype(np.float32) / 255
    a = arl[y0:y0 + side, x0:x0 + side].astype(np.float32) / 255
    p = cv2.resize(p, (CROP, CROP), interpolation=cv2.INTER_AREA if side > CROP else cv2.INTER_LINEAR)
    a = cv2.resize(a, (CROP, CROP), interpolation=cv2.INTER_LINEAR)
    k = rng.integers(0, 4)
    p, a = np.rot90(p, k), np.rot90(a, k)
    if rng.random() < 0.5:
        p, a = p[:, ::-1], a[:, ::-1]
    p = np.ascontiguousarray(p)
    a = np.ascontiguousarray(a)
    yy, xx = np.mgrid[0:CROP, 0:CROP].astype(np.float32) / CROP - 0.5
    # Uneven light, white balance, exposure, gamma, contrast.
    angle = rng.uniform(0, 2 * math.pi)
    light = 1 + rng.uniform(0, 0.3) * (math.cos(angle) * xx + math.sin(angle) * yy)
    p = p * light[..., None] * rng.uniform(0.8, 1.2, 3).astype(np.float32) * rng.uniform(0.6, 1.3)
    p = np.clip(p, 0, 1) ** rng.uniform(0.7, 1.4)
    mean = p.mean()
    p = mean + (p - mean) * rng.uniform(0.5, 1.5)
    if rng.random() < 0.15:
        p = np.repeat(p.mean(2, keepdims=True), 3, 2)
    # Saw marks (periodic stripes) and sanding scratches (thin straight lines).
    if rng.random() < 0.3:
        t = rng.uniform(0, math.pi)
        period = rng.uniform(6, 30) / CROP
        stripes = np.sin(2 * math.pi * (math.cos(t) * xx + math.sin(t) * yy) / period)
        p = p + rng.uniform(0.01, 0.06) * stripes[..., None]
    if rng.random() < 0.3:
        scratches = np.zeros((CROP, CROP), np.float32)
        t = rng.uniform(0, math.pi)
        for _ in range(rng.integers(5, 40)):
            c = rng.uniform(-CROP, 2 * CROP, 2)
            d = np.array([math.cos(t), math.sin(t)]) * CROP
            cv2.line(scratches, tuple(int(v) for v in c - d), tuple(int(v) for v in c + d),
                     float(rng.uniform(-1, 1)), 1)
        p = p + rng.uniform(0.02, 0.08) * scratches[..., None]
    if rng.random() < 0.5:
        p = cv2.GaussianBlur(p, (0, 0), rng.uniform(0.3, 1.3))
    p = p + rng.normal(0, rng.uniform(0, 0.04), p.shape).astype(np.float32)
    p = np.clip(p, 0, 1)
    if rng.random() < 0.5:
        ok, enc = cv2.imencode(".jpg", (p * 255).astype(np.uint8), [cv2.IMWRITE_JPEG_QUALITY, int(rng.integers(30, 95))])
        p = cv2.imdecode(enc, cv2.IMREAD_COLOR).astype(np.float32) / 255
    return normalise(p.astype(np.float32)), a


def batch(photos, arls, indices, rng):
    xs, ys = [], []
    for i in indices:
        x, y = augment(photos[i], arls[i], rng)
        xs.append(x)
        ys.append(y[None])
    return torch.from_numpy(np.stack(xs)), torch.from_numpy(np.stack(ys))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("data", nargs="+", help="folders written by kerf_ring_training_data")
    ap.add_argument("out")
    ap.add_argument("--minutes", type=float, default=20)
    ap.add_argument("--batch", type=int, default=16)
    ap.add_argument("--width", type=int, default=16)
    ap.add_argument("--lr", type=float, default=3e-3)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--init", help="start from these weights (a .pt written next to an earlier output)")
    args = ap.parse_args()
    torch.manual_seed(args.seed)
    torch.set_num_threads(args.threads)
    rng = np.random.default_rng(args.seed)
    stems, photos, arls = [], [], []
    for k, folder in enumerate(args.data):
        s, p, a = load(folder)
        stems += [f"{k}:{stem}" for stem in s]  # block ids stay apart between folders
        photos += p
        arls += a
    # Whole blocks held out for validation (the stem before '_' names the block).
    blocks = sorted({s.split('_')[0] for s in stems})
    held = set(blocks[:: 10])
    train = [i for i, s in enumerate(stems) if s.split('_')[0] not in held]
    val = [i for i, s in enumerate(stems) if s.split('_')[0] in held]
    print(f"{len(stems)} faces of {len(blocks)} blocks: {len(train)} to train on, {len(val)} to validate "
          f"({len(held)} blocks)", flush=True)
    vrng = np.random.default_rng(12345)
    vx, vy = batch(photos, arls, [val[i % len(val)] for i in range(64)], vrng)

    net = RingNet(args.width)
    if args.init:
        net.load_state_dict(torch.load(args.init))
    print(f"parameters: {sum(p.numel() for p in net.parameters())}", flush=True)
    opt = torch.optim.AdamW(net.parameters(), lr=args.lr, weight_decay=1e-4)
    start = time.time()
    budget = args.minutes * 60
    step = 0
    while True:
        elapsed = time.time() - start
        if elapsed > budget:
            break
        for g in opt.param_groups:  # cosine decay over the time budget
            g["lr"] = args.lr * 0.5 * (1 + math.cos(math.pi * min(1.0, elapsed / budget)))
        net.train()
        x, y = batch(photos, arls, rng.choice(train, args.batch), rng)
        logits = net(x)
        # Soft-target cross-entropy, the ring pixels weighted up (they are a few percent of the face).
        weight = 1 + 4 * y
        loss = F.binary_cross_entropy_with_logits(logits, y, weight=weight)
        opt.zero_grad()
        loss.backward()
        opt.step()
        step += 1
        if step % 100 == 0:
            net.eval()
            with torch.no_grad():
                vp = torch.sigmoid(net(vx))
                vloss = F.binary_cross_entropy(vp, vy, weight=1 + 4 * vy).item()
                ring, pred = vy > 200 / 255, vp > 200 / 255
                inter = (ring & pred).sum().item()
                iou = inter / max(1, (ring | pred).sum().item())
            print(f"step {step:5d}  {elapsed / 60:5.1f} min  train {loss.item():.4f}  validation {vloss:.4f}  "
                  f"ring-band IoU {iou:.3f}", flush=True)
    net.eval()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    torch.save(net.state_dict(), os.path.splitext(args.out)[0] + ".pt")  # for --init; not shipped
    torch.onnx.export(Exported(net), torch.zeros(1, 3, 256, 256), args.out, opset_version=11,
                      input_names=["photo"], output_names=["arl"],
                      dynamic_axes={"photo": {2: "height", 3: "width"}, "arl": {2: "height", 3: "width"}})
    print(f"wrote {args.out} ({os.path.getsize(args.out)} bytes) after {step} steps, "
          f"{(time.time() - start) / 60:.1f} min", flush=True)


if __name__ == "__main__":
    main()
