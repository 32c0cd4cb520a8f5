#!/usr/bin/env python3
"""Writes the HoloOcean / NeuSIS dataset of tests/data/holoocean/ with Python's pickle and numpy
(Debian's python3-numpy, 1.24): an independent writer of what the decoder reads
(core/io/pickle/). Not run by the test suite; run it by hand from this folder.

Four frames, one per pickle protocol 2 to 5, each a dict as HoloOcean's env.tick() returns and
NeuSIS pickles it: ImagingSonar (8 range bins x 6 beams, float32, one bright pixel: row k + 1,
HoloOcean's column 0, value 0.5 + k), PoseSensor (4 x 4: a yaw of 30 k degrees about z up, at
x = k, y = 0.5, z = -4), and other sensors' readings the reader passes over (a float32 scalar,
a float64 array, a bool, a str). Frame 1's image is in Fortran order, frame 2's pose big-endian
float64. The files are named 0, 5, 10, 15 so that natural order differs from byte order.
"""
import json
import math
import pickle

import numpy as np

config = {
    "name": "sonarcarve-numpy-check",
    "ticks_per_sec": 10,
    "agents": [{
        "agent_name": "auv0",
        "sensors": [
            {"sensor_type": "PoseSensor", "socket": "SonarSocket"},
            {"sensor_type": "ImagingSonar", "socket": "SonarSocket", "Hz": 5,
             "configuration": {"RangeMin": 1, "RangeMax": 9, "RangeBins": 8, "Azimuth": 120,
                               "AzimuthBins": 6, "Elevation": 20}},
        ],
    }],
}
with open("Config.json", "w") as f:
    json.dump(config, f, indent=2)

for k, protocol in enumerate([2, 3, 4, 5]):
    image = np.zeros((8, 6), np.float32)
    image[k + 1, 0] = 0.5 + k
    a = math.radians(30 * k)
    pose = np.eye(4, dtype=np.float32)
    pose[:3, :3] = [[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]]
    pose[:3, 3] = [k, 0.5, -4]
    if k == 1:
        image = np.asfortranarray(image)
    if k == 2:
        pose = pose.astype(">f8")
    state = {"ImagingSonar": image, "PoseSensor": pose, "t": np.float32(k * 0.2),
             "DepthSensor": np.array([4.0]), "flag": True, "name": "auv0"}
    with open(f"Data/{k * 5}.pkl", "wb") as f:
        pickle.dump(state, f, protocol=protocol)
