"""The per-frame overhead of the Python call against the C++ call (issue
#17): the same frames and gaze through eyestream.Eye.process (Python, numpy
in, numpy out) and eyestream::Eye::process (bench/api_call_bench.cpp), in
one run, alternating, the median of each. Times, never asserts.

    PYTHONPATH=build/python python3 bench/api_overhead.py [build]
"""
import resource
import statistics
import subprocess
import sys
import time

import numpy as np

import eyestream

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
FPS, FRAMES, ROUNDS, QUALITY = 30.0, 30, 3, "fast"


def frames(width, height):
    """The frames and gaze api_call_bench.cpp makes, frame 0 first."""
    out = []
    for n in range(FRAMES + 1):
        frame = np.full((height, width, 3), 0.3, np.float32)
        lamp, side = width // 8 + (n * width // 40) % (width * 3 // 4), max(2, width // 80)
        top = height // 2 - side // 2
        frame[top:top + side, lamp:lamp + side] = 1e4
        out.append((frame, [(n / FPS, lamp + side / 2.0, height / 2.0)]))
    return out


def python_ms(width, height, data):
    eye = eyestream.Eye(width, height, FPS, quality=QUALITY)
    eye.process(*data[0])
    faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    start = time.perf_counter()
    for frame, gaze in data[1:]:
        eye.process(frame, gaze)
    ms = 1e3 * (time.perf_counter() - start) / FRAMES
    return ms, (resource.getrusage(resource.RUSAGE_SELF).ru_minflt - faults) / FRAMES


def cpp_ms(width, height):
    out = subprocess.run([f"{BUILD}/bench/eyestream_api_call_bench", str(width), str(height), str(FRAMES), QUALITY],
                         check=True, capture_output=True, text=True).stdout
    words = out.split()
    return float(words[1]), float(words[3])


print(f"{QUALITY}, {FRAMES} frames a round, {ROUNDS} rounds alternating; ms per frame (median)")
print("size        C++      Python   Python - C++        page faults a frame: C++, Python")
for width, height in ((64, 36), (320, 180), (1280, 720)):
    data = frames(width, height)
    py, cc = [], []
    for _ in range(ROUNDS):
        cc.append(cpp_ms(width, height))
        py.append(python_ms(width, height, data))
    c, p = statistics.median(m for m, _ in cc), statistics.median(m for m, _ in py)
    fc, fp = statistics.median(f for _, f in cc), statistics.median(f for _, f in py)
    print(f"{width}x{height:<6} {c:8.2f} {p:8.2f} {p - c:+10.2f} ({100 * (p - c) / c:+5.1f} %)   {fc:8.0f} {fp:8.0f}")
