#!/usr/bin/env python3
"""Writes the small seed inputs of the fuzz targets into tests/fuzz/corpus/<target>/.

Run from the repository root. Crash inputs found by fuzzing are kept beside the seeds
(named crash-*, oom-*, timeout-*) and replayed by the unit test FuzzRegression.
"""
import math
import struct
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus"


def oculus_ping(version=0, beams=16, ranges=10, sixteen=False, gain=False, ping_id=1, t=0.0):
    """A simple ping result laid out as in the public Oculus.h (packed)."""
    v2 = version == 2
    fixed = 202 if v2 else 122
    table = [round(100 * math.degrees(math.asin((-1 + 2 * (j + 0.5) / beams) * math.sin(math.pi / 4))))
             for j in range(beams)]
    image_offset = (fixed + 2 * beams + 7) // 8 * 8
    sample = 2 if sixteen else 1
    row = beams * sample + (4 if gain else 0)
    size = image_offset + row * ranges
    b = struct.pack("<HHHHHIH", 0x4F53, 1, 0, 0x23, version, size - 16, 0)
    flags = 0x09 | (0x02 if sixteen else 0) | (0x04 if gain else 0)
    b += struct.pack("<BBBBBdddd", 2, 0, 0, 0, flags, 5.0, 60.0, 0.0, 35.0)
    if v2:
        b += struct.pack("<I", 0) + bytes(32)
    b += struct.pack("<IIddd", ping_id, 0, 2.1e6, 12.5, 3.25)
    if v2:
        b += struct.pack("<ddd", 90.0, 1.0, -1.0)
    b += struct.pack("<d", 1500.0)
    b += struct.pack("<d", t) if v2 else struct.pack("<I", int(t))
    b += struct.pack("<BdHH", 1 if sixteen else 0, 0.01, ranges, beams)
    if v2:
        b += bytes(16)
    b += struct.pack("<III", image_offset, row * ranges, size)
    assert len(b) == fixed
    b += struct.pack("<%dh" % beams, *table)
    b += bytes(image_offset - len(b))
    for r in range(ranges):
        if gain:
            b += struct.pack("<I", 1000 + r)
        for c in range(beams):
            v = r * 31 + c * 7
            b += struct.pack("<H", v * 257 % 65536) if sixteen else bytes([v % 256])
    return b


def message(msg_id, payload):
    return struct.pack("<HHHHHIH", 0x4F53, 1, 0, msg_id, 0, len(payload), 0) + payload


def recording(items):
    b = struct.pack("<II16sHH4xqd", 0x11223344, 48, b"Oculus", 1, 0, 0, 1.7e9)
    for item_type, t, payload, compress in items:
        stored = struct.pack(">I", len(payload)) + zlib.compress(payload) if compress else payload
        b += struct.pack("<IIHH4xdH2xII4x", 0xAABBCCDD, 40, item_type, 0, t, 1 if compress else 0,
                         len(payload), len(stored))
        b += stored
    return b


def write(target, name, data):
    folder = CORPUS / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def ply_binary():
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
              "property float y\nproperty float z\nproperty uint views\nend_header\n").encode()
    body = b"".join(struct.pack("<fffI", i, 2 * i, -i, i) for i in range(3))
    return header + body


def stl_binary():
    tri = struct.pack("<12fH", 0, 0, 1, 2, 0, 10, 2.1, 0, 10, 2, 0.1, 10, 0)
    return b"solid-less binary".ljust(80, b" ") + struct.pack("<I", 2) + tri + tri


NOISE_MODEL = """%YAML:1.0
---
format: sonarcarve-noise-model
version: 1
frames: 3
smoothing: 1
range_min_m: 1.
range_resolution_m: 0.025
vertical_aperture_rad: 0.349
bearings_rad: !!opencv-matrix
   rows: 1
   cols: 2
   dt: d
   data: [ -0.1, 0.1 ]
mean: !!opencv-matrix
   rows: 2
   cols: 2
   dt: f
   data: [ 1., 2., 3., 4. ]
stddev: !!opencv-matrix
   rows: 2
   cols: 2
   dt: f
   data: [ 0.5, 0.5, 0.5, 0.5 ]
rayleigh_sigma: !!opencv-matrix
   rows: 2
   cols: 2
   dt: f
   data: [ 1., 1., 1., 1. ]
"""


def aris_recording(frames=2, samples=4):
    """An ARIS file: the file header, then frames of 48 beams (ping mode 1) with the sample
    fixture's geometry but only `samples` samples per beam (field offsets: FrameHeader.h)."""
    b = bytearray(1024)
    struct.pack_into("<II", b, 0, 0x05464444, frames)
    for k in range(frames):
        h = bytearray(1024)
        struct.pack_into("<IQ", h, 0, k, 1371198079122519 + 152500 * k)
        for at, value in ((436, 1), (452, 14), (468, samples), (476, 4593), (480, 1), (516, 1)):
            struct.pack_into("<I", h, at, value)
        struct.pack_into("<f", h, 464, 1435.93)
        b += h + bytes((7 * i + k) % 256 for i in range(48 * samples))
    return bytes(b)


def main():
    write("oculus", "v0_8bit", oculus_ping(0, 16, 10))
    write("oculus", "v2_16bit_gain", oculus_ping(2, 8, 4, sixteen=True, gain=True))
    write("oculus", "stream_with_status",
          oculus_ping(1, 8, 3, t=5) + message(0x80, b"status!") + oculus_ping(1, 8, 3, t=6))
    write("oculus", "recording",
          recording([(1, 1.0, b"settings", False), (10, 2.0, oculus_ping(0, 8, 3), False),
                     (10, 3.0, oculus_ping(2, 8, 3, gain=True), True)]))

    example = ROOT / "resources" / "example_mission"
    write("mission", "example",
          b"\0".join((example / f).read_bytes() for f in ("mission.yaml", "nav.csv", "frames.csv")))
    write("frame_png", "example_frame.png", (example / "frames" / "000000.png").read_bytes())
    write("ply", "ascii.ply",
          "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
          "property float z\nproperty float intensity\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n0 0 0 1\n1 2 3 4\n3 0 1 1\n")
    write("ply", "binary.ply", ply_binary())
    write("nav_import", "feet_compass",
          "delimiter: ';'\ncolumns: {time: t, north: n, east: e, depth: z, heading: h, pitch: 5}\n"
          "units: {time: ms, position: ft, angles: deg}\nconventions: {heading: compass}\n\0"
          "t;n;e;z;h;p\n1000;1;2;3;90;1\n2000;2;3;4;180;-1\n")
    write("nav_import", "indices_enu",
          "header: false\ncolumns: {time: 0, north: 2, east: 1, up: 3, yaw: 4}\n"
          "units: {angles: rad}\nconventions: {heading: enu, pitch: bow_down, roll: port_down}\n\0"
          "0,1,2,-3,0.5\n1,1,2,-3,0.6\n")

    write("params_yaml", "some_keys",
          "voxel_size_m: 0.05\nelevation_step_deg: 0.5\nengine: fast\nregion: [0, 0, 0, 1, 1, 1]\n")
    write("params_yaml", "nested", "carve:\n  voxel_size_m: 0.1\nmesh: false\nframes: {first: 2}\n")
    write("noise_model", "two_by_two.yaml", NOISE_MODEL)
    write("mesh", "ascii.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 2 0 10\n"
          "vertex 2.1 0 10\nvertex 2 0.1 10\nendloop\nendfacet\nendsolid t\n")
    write("mesh", "binary.stl", stl_binary())
    write("mesh", "tetrahedron.obj", "# a tetrahedron\nv 2 0 10\nv 2.1 0 10\nv 2 0.1 10\n"
          "v 2 0 10.1\nvn 0 0 1\nf 1 2 3\nf 1//1 2//1 4//1\nf 1/1 3/1 4/1\nf 2 3 4\n")
    write("mesh", "faces.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n2 0 10\n2.1 0 10\n2 0.1 10\n3 0 1 2\n")
    write("session", "full.sonarcarve",
          "# SonarCarve GUI session\nformat: sonarcarve-session\nversion: 1\n"
          "mission: /data/mission\nframe: 12\ncolour_by: depth\n"
          "camera: {position: [1, 2, 3], focal_point: [0, 0, 10], view_up: [0, 0, -1], "
          "parallel: true, parallel_scale: 2.5, view_angle_deg: 30}\n"
          "params: {voxel_size_m: 0.05, engine: fast, detector: {mode: cfar}}\n")
    write("session", "minimal.sonarcarve",
          "format: sonarcarve-session\nversion: 1\nmission: m\n")
    write("aris", "two_frames.aris", aris_recording())
    write("aris", "cut_second_frame.aris", aris_recording()[:-10])


if __name__ == "__main__":
    main()
