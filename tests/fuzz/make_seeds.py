#!/usr/bin/env python3
"""Writes the small seed inputs of the fuzz targets into tests/fuzz/corpus/<target>/.

Run from the repository root. Crash inputs found by fuzzing are kept beside the seeds
(named crash-*, oom-*, timeout-*) and replayed by the unit test FuzzRegression.
"""
import math
import sqlite3
import struct
import subprocess
import tempfile
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


class Cdr:
    """Little-endian CDR: primitives aligned to their size after the 4-byte header."""

    def __init__(self):
        self.b = bytearray(b"\x00\x01\x00\x00")

    def put(self, fmt, *values):
        size = struct.calcsize("<" + fmt[-1])
        while (len(self.b) - 4) % size:
            self.b.append(0)
        self.b += struct.pack("<" + fmt, *values)

    def string(self, text):
        self.put("I", len(text) + 1)
        self.b += text.encode() + b"\0"

    def header(self, t_ns, frame):
        self.put("i", t_ns // 10**9)
        self.put("I", t_ns % 10**9)
        self.string(frame)


def sonar_image(t_ns, beams=4, ranges=5):
    c = Cdr()
    c.header(t_ns, "sonar")
    c.put("ff", 900e3, 1500.0)
    c.put("I", beams)
    c.put("%df" % beams, *([0.35] * beams))
    c.put("I", 0)
    c.put("I", beams)
    for j in range(beams):
        a = math.radians(-30 + 60 * (j + 0.5) / beams)
        c.put("ddd", 0.0, math.sin(a), math.cos(a))
    c.put("I", ranges)
    c.put("%df" % ranges, *[0.5 + 0.1 * r for r in range(ranges)])
    c.put("B", 0)
    c.put("III", 0, beams, beams * ranges)
    c.b += bytes((7 * i) % 256 for i in range(beams * ranges))
    return bytes(c.b)


def odometry(t_ns, x):
    c = Cdr()
    c.header(t_ns, "odom")
    c.string("base_link")
    c.put("ddddddd", x, 0.0, -2.0, 0.0, 0.0, 0.0, 1.0)
    c.put("36d", *([0.0] * 36))
    c.put("42d", *([0.0] * 42))
    return bytes(c.b)


def tf_static():
    c = Cdr()
    c.put("I", 1)
    c.header(0, "base_link")
    c.string("sonar")
    c.put("ddddddd", 0.3, 0.0, 0.0, 0.5, -0.5, 0.5, -0.5)
    return bytes(c.b)


BAG_TOPICS = [("/sonar/image", "marine_acoustic_msgs/msg/ProjectedSonarImage"),
              ("/odom", "nav_msgs/msg/Odometry"), ("/tf_static", "tf2_msgs/msg/TFMessage")]


def bag_messages():
    """(topic index, time ns, CDR bytes) of a tiny bag: mounting, 3 poses, 2 sonar pings."""
    out = [(2, 0, tf_static())]
    out += [(1, k * 10**9, odometry(k * 10**9, 0.1 * k)) for k in range(3)]
    out += [(0, k * 10**9 + 5 * 10**8, sonar_image(k * 10**9 + 5 * 10**8)) for k in range(2)]
    return sorted(out, key=lambda m: m[1])


def mcap_record(op, content):
    return struct.pack("<BQ", op, len(content)) + content


def mcap_string(text):
    return struct.pack("<I", len(text)) + text.encode()


def compress(tool, data):
    if tool == "":
        return data
    return subprocess.run([tool, "-q", "-c"], input=data, stdout=subprocess.PIPE, check=True).stdout


def mcap_bag(chunks=None):
    """An MCAP file of bag_messages(): messages in the data section (chunks None) or in one
    chunk compressed with "", "lz4" or "zstd"; no summary section."""
    b = b"\x89MCAP0\r\n" + mcap_record(1, mcap_string("ros2") + mcap_string("make_seeds"))
    for i, (topic, type_name) in enumerate(BAG_TOPICS):
        b += mcap_record(3, struct.pack("<H", i + 1) + mcap_string(type_name) +
                         mcap_string("ros2msg") + mcap_string(""))
        b += mcap_record(4, struct.pack("<HH", i + 1, i + 1) + mcap_string(topic) +
                         mcap_string("cdr") + struct.pack("<I", 0))
    records = b"".join(mcap_record(5, struct.pack("<HIQQ", t + 1, n, ns, ns) + data)
                       for n, (t, ns, data) in enumerate(bag_messages()))
    if chunks is None:
        b += records
    else:
        stored = compress(chunks, records)
        b += mcap_record(6, struct.pack("<QQQI", 0, 2 * 10**9, len(records), zlib.crc32(records)) +
                         mcap_string(chunks) + struct.pack("<Q", len(stored)) + stored)
    b += mcap_record(15, struct.pack("<I", 0)) + mcap_record(2, bytes(20)) + b"\x89MCAP0\r\n"
    return b


def legacy_sonar_image(t_ns, beams=4, ranges=5):
    """The older acoustic_msgs/SonarImage: azimuths, azimuth-major uint16 intensities."""
    c = Cdr()
    c.header(t_ns, "sonar_ned")
    c.put("ffff", 900e3, 1500.0, 0.02, 0.35)
    c.put("I", beams)
    c.put("%df" % beams, *[math.radians(-30 + 60 * (j + 0.5) / beams) for j in range(beams)])
    c.put("I", 0)
    c.put("I", ranges)
    c.put("%df" % ranges, *[0.5 + 0.1 * r for r in range(ranges)])
    c.put("B", 0)
    c.put("B", 2)
    c.put("I", 2 * beams * ranges)
    c.b += b"".join(struct.pack("<H", 300 * i) for i in range(beams * ranges))
    return bytes(c.b)


def legacy_mcap_bag():
    b = b"\x89MCAP0\r\n" + mcap_record(1, mcap_string("ros2") + mcap_string("make_seeds"))
    b += mcap_record(3, struct.pack("<H", 1) + mcap_string("acoustic_msgs/msg/SonarImage") +
                     mcap_string("ros2msg") + mcap_string(""))
    b += mcap_record(4, struct.pack("<HH", 1, 1) + mcap_string("/sonar") + mcap_string("cdr") +
                     struct.pack("<I", 0))
    for n in range(2):
        b += mcap_record(5, struct.pack("<HIQQ", 1, n, n, n) + legacy_sonar_image(n * 10**9))
    return b + mcap_record(15, struct.pack("<I", 0)) + mcap_record(2, bytes(20)) + b"\x89MCAP0\r\n"


def db3_bag(compress_messages=False):
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bag.db3"
        db = sqlite3.connect(path)
        db.executescript(
            "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
            "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
            "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
            "timestamp INTEGER NOT NULL, data BLOB NOT NULL);")
        db.executemany("INSERT INTO topics VALUES(?, ?, ?, 'cdr', '')",
                       [(i + 1, name, type_name) for i, (name, type_name) in enumerate(BAG_TOPICS)])
        db.executemany("INSERT INTO messages(topic_id, timestamp, data) VALUES(?, ?, ?)",
                       [(t + 1, ns, compress("zstd", data) if compress_messages else data)
                        for t, ns, data in bag_messages()])
        db.commit()
        db.close()
        return path.read_bytes()


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def inflation_bomb_png(rows=32, cols=32, inflated_mib=8):
    """A 16-bit grey PNG declaring rows x cols whose image data inflates to far more (zeros):
    the class of file that made every read inflate 12 GB (issue 44)."""
    idat = zlib.compress(bytes(inflated_mib << 20), 9)
    ihdr = struct.pack(">IIBBBBB", cols, rows, 16, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", idat)
            + png_chunk(b"IEND", b""))


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
    write("frame_png", "inflation_bomb.png", inflation_bomb_png())
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
    write("mcap", "unchunked.mcap", mcap_bag())
    write("mcap", "chunk_none.mcap", mcap_bag(""))
    write("mcap", "chunk_lz4.mcap", mcap_bag("lz4"))
    write("mcap", "chunk_zstd.mcap", mcap_bag("zstd"))
    write("mcap", "cut_short.mcap", mcap_bag("zstd")[:-60])
    write("mcap", "legacy_sonar_image.mcap", legacy_mcap_bag())
    write("db3", "tiny.db3", db3_bag())
    write("db3", "messages_zstd.db3", db3_bag(compress_messages=True))


if __name__ == "__main__":
    main()
