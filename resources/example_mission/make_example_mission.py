#!/usr/bin/env python3
"""Writes the small example mission shipped with SonarCarve (format v1, docs/formats.md).

A sonar looking north, level, descends past a vertical pipe 0.4 m in diameter standing
4.5 m ahead, in 10 cm steps (the seed paper's vertical inspection, at a smaller scale).
Each pixel sums the beam-pattern-weighted returns of its elevation arc from the pipe's
front surface, plus Rayleigh speckle. Standard library only; reproducible (fixed seed).
Run from this folder: python3 make_example_mission.py
"""
import math
import random
import struct
import zlib
from pathlib import Path

SONAR_ID = "example-sonar"
BEAMS, FOV_DEG = 64, 60.0
BINS, MIN_RANGE, RES = 200, 1.0, 0.025
APERTURE_DEG = 20.0
FRAMES, STEP_M, DT_S = 10, 0.10, 0.5
PIPE_NORTH, PIPE_RADIUS = 4.5, 0.2


def sinc_weight(theta, aperture):
    """Intensity weight, -3 dB at +-aperture/2 (same definition as core/sonar/beam_pattern)."""
    lo, hi, target = 1e-9, math.pi, 10 ** -0.3
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if math.sin(mid) / mid > target else (lo, mid)
    x = abs(0.5 * (lo + hi) / (0.5 * aperture) * theta)
    return 1.0 if x < 1e-12 else (0.0 if x >= math.pi else math.sin(x) / x)


def pipe_range(bearing, elevation):
    """Range along a ray (sonar frame x north, y east, z down) to the pipe, or None."""
    dx = math.cos(elevation) * math.cos(bearing)
    dy = math.cos(elevation) * math.sin(bearing)
    a = dx * dx + dy * dy
    b = -2.0 * dx * PIPE_NORTH
    c = PIPE_NORTH ** 2 - PIPE_RADIUS ** 2
    disc = b * b - 4 * a * c
    if disc < 0:
        return None
    return (-b - math.sqrt(disc)) / (2 * a)


def png16(rows):
    raw = b"".join(b"\x00" + struct.pack(">%dH" % len(r), *r) for r in rows)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", len(rows[0]), len(rows), 16, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    rng = random.Random(20151)
    out = Path(__file__).resolve().parent
    (out / "frames").mkdir(exist_ok=True)
    aperture = math.radians(APERTURE_DEG)
    fov = math.radians(FOV_DEG)
    thetas = [aperture * (k / 40.0 - 0.5) * 1.6 for k in range(41)]
    index = ["time_s,sonar_id,file"]
    nav = ["time_s,north_m,east_m,down_m,roll_deg,pitch_deg,yaw_deg"]
    for f in range(FRAMES):
        image = [[0.0] * BEAMS for _ in range(BINS)]
        for j in range(BEAMS):
            bearing = -0.5 * fov + (j + 0.5) * fov / BEAMS
            for theta in thetas:
                r = pipe_range(bearing, theta)
                if r is None:
                    continue
                row = int((r - MIN_RANGE) / RES)
                if 0 <= row < BINS:
                    image[row][j] += 900.0 * sinc_weight(theta, aperture)
        rows = []
        for row in image:
            out_row = []
            for v in row:
                speckle = math.sqrt(-2.0 * math.log(1.0 - rng.random()))  # Rayleigh, mean 1.25
                out_row.append(min(65535, int(round(v * speckle + 40.0 * speckle))))
            rows.append(out_row)
        name = "frames/%06d.png" % f
        (out / name).write_bytes(png16(rows))
        t = 100.0 + f * DT_S
        index.append("%g,%s,%s" % (t, SONAR_ID, name))
    for k in range(FRAMES + 1):
        t = 100.0 - 0.25 + k * DT_S
        down = 10.0 + STEP_M * (t - 100.0) / DT_S
        nav.append("%g,%g,%g,%g,0,0,0" % (t, 0.0, 0.0, round(down, 6)))
    (out / "frames.csv").write_text("\n".join(index) + "\n")
    (out / "nav.csv").write_text("\n".join(nav) + "\n")


if __name__ == "__main__":
    main()
