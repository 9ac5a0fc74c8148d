"""The Python module against the command line and itself.

Run by ctest (tests/CMakeLists.txt) with PYTHONPATH at the built module and
EYESTREAM at the built program. The command line's PNG frames are decoded
here with zlib alone (an independent reader), and the module's encoded
frames must equal them byte for byte.
"""
import os
import struct
import subprocess
import sys
import tempfile
import threading
import unittest
import zlib

import numpy as np

import eyestream

W, H, FPS, FRAMES = 64, 48, 30.0, 8


def scene(n):
    """Frame n: a 0.05-50 cd/m^2 ramp and a 2e4 cd/m^2 light moving right."""
    y, x = np.mgrid[0:H, 0:W].astype(np.float32)
    frame = np.empty((H, W, 3), np.float32)
    ramp = 0.05 * 1000.0 ** (x / (W - 1))
    frame[..., 0] = ramp
    frame[..., 1] = ramp * 0.8
    frame[..., 2] = ramp * (0.5 + 0.5 * y / (H - 1))
    frame[20:23, 10 + 4 * n:13 + 4 * n, :] = 2e4
    return frame


def gaze_log():
    """A sample every 10 ms moving across, with a blink from 0.09 to 0.14 s."""
    rows = []
    for i in range(int(FRAMES / FPS / 0.01) + 1):
        t = round(0.01 * i, 3)
        closed = 0.09 <= t < 0.14
        rows.append((t, 20.0 + 3.0 * i, 24.0 - 0.5 * i, closed))
    return rows


def samples_of_frame(log, n):
    t0, t1 = n / FPS, (n + 1) / FPS
    return [r for r in log if t0 <= r[0] < t1]


def read_png_rgb8(path):
    """An 8-bit RGB PNG's pixels, decoded with zlib and the PNG filters."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, interlace) == (8, 2, 0), (depth, colour, interlace)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride, bpp = width * 3, 3
    out = np.zeros((height, stride), np.uint8)
    prev = np.zeros(stride, np.int32)
    for r in range(height):
        kind = raw[r * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, r * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, np.int32)
        for i in range(stride):
            a = cur[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 0:
                pred = 0
            elif kind == 1:
                pred = a
            elif kind == 2:
                pred = b
            elif kind == 3:
                pred = (a + b) // 2
            else:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[i] = (line[i] + pred) & 0xFF
        out[r] = cur
        prev = cur
    return out.reshape(height, width, 3)


def command_line_frames(d, log, *options):
    """`eyestream run` on the scene's frames (raw standard input) with `log`
    as its gaze CSV and `options`: the folder of its PNGs."""
    with open(os.path.join(d, "gaze.csv"), "w") as f:
        f.write("t,x,y,event\n")
        for t, x, y, closed in log:
            f.write(f"{t:.3f},{x:.1f},{y:.1f},{'blink' if closed else ''}\n")
    raw = b"".join(scene(n).tobytes() for n in range(FRAMES))
    out = os.path.join(d, "out")
    cmd = [os.environ["EYESTREAM"], "run", "-i", "-", "--size", f"{W}x{H}", "--fps", str(FPS),
           "--gaze", os.path.join(d, "gaze.csv"), *options, "-o", os.path.join(out, "%05d.png")]
    subprocess.run(cmd, input=raw, check=True, capture_output=True)
    return out


class MatchesTheCommandLine(unittest.TestCase):
    def test_every_frame_is_the_command_lines_byte_for_byte(self):
        log = gaze_log()
        with tempfile.TemporaryDirectory() as d:
            out = command_line_frames(d, log, "--viewer-age", "70", "--quality", "fast")
            eye = eyestream.Eye(W, H, FPS, viewer_age=70, quality="fast")
            for n in range(FRAMES):
                eye.process(scene(n), [(t, x, y, c) for t, x, y, c in samples_of_frame(log, n)])
                expected = read_png_rgb8(os.path.join(out, f"{n:05d}.png"))
                self.assertTrue(np.array_equal(eye.code, expected), f"frame {n}")
            self.assertTrue(any(r[3] for r in log), "the log has a blink")

    def test_a_whole_recording_is_read_as_the_command_line_reads_its_log(self):
        # The log starts 50 ms in (frame 1): the command line holds its first
        # sample back to frame 0, and so does an eye given the whole recording.
        log = [r for r in gaze_log() if r[0] >= 0.05]
        with tempfile.TemporaryDirectory() as d:
            out = command_line_frames(d, log, "--quality", "fast")
            eye = eyestream.Eye(W, H, FPS, quality="fast")
            eye.set_gaze(log)
            for n in range(FRAMES):
                eye.process(scene(n))
                expected = read_png_rgb8(os.path.join(out, f"{n:05d}.png"))
                self.assertTrue(np.array_equal(eye.code, expected), f"frame {n}")
                if n == 0:
                    self.assertEqual(eye.report["gaze_x"], log[0][1], "the first sample held back to frame 0")
            self.assertGreater(eye.report["glare_ms"] + eye.report["retina_ms"], 0.0)
            with self.assertRaises(eyestream.Error):
                eye.process(scene(0), [(0.5, 1.0, 1.0)])

    def test_the_readers_feed_an_eye_the_frames_and_gaze_the_command_line_reads(self):
        # A built-in scene's EXR frames and gaze log, read by eyestream.Frames
        # and eyestream.read_gaze, through an Eye: the command line's PNGs.
        with tempfile.TemporaryDirectory() as d:
            subprocess.run([os.environ["EYESTREAM"], "sample", "night-drive", "-o", os.path.join(d, "nd"),
                            "--width", "64", "--height", "36", "--duration", "0.3"], check=True, capture_output=True)
            frames_in, gaze_in = os.path.join(d, "nd", "frames"), os.path.join(d, "nd", "gaze.csv")
            subprocess.run([os.environ["EYESTREAM"], "run", "-i", frames_in, "-g", gaze_in, "--quality", "fast",
                            "-o", os.path.join(d, "out", "%05d.png")], check=True, capture_output=True)
            frames = eyestream.Frames(frames_in)
            self.assertEqual((frames.width, frames.height, frames.frame_count), (64, 36, 9))
            gaze = eyestream.read_gaze(gaze_in, frames.width, frames.height, frames.fps)
            self.assertEqual(gaze.shape[1], 6)
            eye = eyestream.Eye(frames.width, frames.height, frames.fps, quality="fast")
            count = 0
            for frame, t, n in frames:
                self.assertAlmostEqual(t, n / frames.fps, places=9)
                mine = gaze[(gaze[:, 0] >= n / frames.fps) & (gaze[:, 0] < (n + 1) / frames.fps)]
                # The command line holds the log's first sample back to frame 0.
                if n == 0:
                    mine = np.vstack([gaze[:1], mine[mine[:, 0] > gaze[0, 0]]]) if gaze[0, 0] > 0 else mine
                eye.process(frame, mine)
                expected = read_png_rgb8(os.path.join(d, "out", f"{n:05d}.png"))
                self.assertTrue(np.array_equal(eye.code, expected), f"frame {n}")
                count += 1
            self.assertEqual(count, 9)
            with self.assertRaises(eyestream.Error) as e:
                eyestream.Frames(os.path.join(d, "missing", "%05d.exr"))
            self.assertEqual(e.exception.args[1], 3)


class Frames(unittest.TestCase):
    def test_views_and_other_dtypes_give_the_same_frames(self):
        packed, strided, doubles = (eyestream.Eye(W, H, FPS) for _ in range(3))
        for n in range(3):
            frame = scene(n)
            wide = np.zeros((H, W + 5, 3), np.float32)
            wide[:, 2:W + 2] = frame
            a = packed.process(frame, [(n / FPS, 30.0, 20.0)])
            b = strided.process(wide[:, 2:W + 2], [(n / FPS, 30.0, 20.0)])  # rows apart by W + 5 pixels
            c = doubles.process(frame.astype(np.float64), np.array([[n / FPS, 30.0, 20.0]]))
            self.assertTrue(np.array_equal(a, b) and np.array_equal(a, c), f"frame {n}")
        self.assertEqual(a.dtype, np.float32)
        self.assertEqual(a.shape, (H, W, 3))

    def test_the_gil_is_free_while_a_frame_is_processed(self):
        eye = eyestream.Eye(640, 360, FPS, quality="reference")
        frame = np.full((360, 640, 3), 0.02, np.float32)  # mesopic: every stage works
        eye.process(frame)  # the first frame sets up
        ticks, done = [0], threading.Event()

        def count():
            while not done.is_set():
                ticks[0] += 1

        # No forced switches within a second: the counter runs inside the
        # window only if process() lets go of the GIL (held, it would count
        # nothing until the window had closed).
        interval = sys.getswitchinterval()
        sys.setswitchinterval(1.0)
        try:
            counter = threading.Thread(target=count)
            counter.start()
            before = ticks[0]
            eye.process(frame)
            during = ticks[0] - before
        finally:
            done.set()
            counter.join()
            sys.setswitchinterval(interval)
        self.assertGreater(during, 1000, "Python ran beside the frame")

    def test_one_eye_from_two_threads_gives_the_frames_of_one(self):
        # Calls into one eye wait for each other: two threads feeding it
        # frames in turn give what one thread gives.
        log = gaze_log()
        alone, shared = eyestream.Eye(W, H, FPS), eyestream.Eye(W, H, FPS)
        expected = [alone.process(scene(n), samples_of_frame(log, n)).copy() for n in range(FRAMES)]
        got, turn = [None] * FRAMES, threading.Condition()
        state = {"next": 0}

        def feed(parity):
            for n in range(parity, FRAMES, 2):
                with turn:
                    turn.wait_for(lambda: state["next"] == n)
                got[n] = shared.process(scene(n), samples_of_frame(log, n)).copy()
                _ = shared.report, shared.code  # read while the other thread may be processing
                with turn:
                    state["next"] += 1
                    turn.notify_all()

        threads = [threading.Thread(target=feed, args=(p,)) for p in (0, 1)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for n in range(FRAMES):
            self.assertTrue(np.array_equal(expected[n], got[n]), f"frame {n}")


    def test_independent_eyes_on_two_threads_give_what_each_gives_alone(self):
        # Two eyes of different viewers, each fed on its own thread at the
        # same time (the GIL is let go while a frame is processed): each
        # gives the frames it gives alone.
        log = gaze_log()
        settings = [dict(quality="fast"), dict(quality="balanced", viewer_age=70)]
        alone = []
        for kw in settings:
            eye = eyestream.Eye(W, H, FPS, **kw)
            alone.append([eye.process(scene(n), samples_of_frame(log, n)).copy() for n in range(FRAMES)])
        together = [[None] * FRAMES for _ in settings]

        def feed(i):
            eye = eyestream.Eye(W, H, FPS, **settings[i])
            for n in range(FRAMES):
                together[i][n] = eye.process(scene(n), samples_of_frame(log, n)).copy()

        threads = [threading.Thread(target=feed, args=(i,)) for i in range(len(settings))]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for i in range(len(settings)):
            for n in range(FRAMES):
                self.assertTrue(np.array_equal(alone[i][n], together[i][n]), f"eye {i}, frame {n}")
        self.assertFalse(np.array_equal(alone[0][FRAMES - 1], alone[1][FRAMES - 1]), "two different eyes")


class StateAndErrors(unittest.TestCase):
    def test_a_restored_eye_goes_on_bit_for_bit(self):
        log = gaze_log()
        first = eyestream.Eye(W, H, FPS, quality="fast")
        for n in range(4):
            first.process(scene(n), samples_of_frame(log, n))
        saved = first.state()
        second = eyestream.Eye(W, H, FPS, quality="fast")
        second.restore(saved)
        for n in range(4, FRAMES):
            a = first.process(scene(n), samples_of_frame(log, n))
            b = second.process(scene(n), samples_of_frame(log, n))
            self.assertTrue(np.array_equal(a, b), f"frame {n}")

    def test_a_pickled_state_restores_and_a_malformed_one_is_refused(self):
        import pickle
        first = eyestream.Eye(W, H, FPS)
        for n in range(3):
            first.process(scene(n), [(n / FPS, 30.0, 20.0)])
        saved = pickle.loads(pickle.dumps(first.state()))
        second = eyestream.Eye(W, H, FPS)
        second.restore(saved)
        self.assertTrue(np.array_equal(first.process(scene(3)), second.process(scene(3))))
        for bad in ([[1.0, 2.0]], "text", None):  # a list, a string, nothing: refused, never read as an array
            with self.assertRaises((TypeError, ValueError)):
                second.restore(([bad] + list(saved[0][1:]), saved[1]))

    def test_a_recorded_pupil_drives_the_optics(self):
        # In scotopic light the lenticular halo needs a pupil over 2.5 mm and
        # is whole from 3.5 mm: a recorded 3 mm pupil shows less of it than
        # the model's wide one.
        recorded = eyestream.Eye(W, H, FPS, pupil_from_gaze=True, report=True)
        modelled = eyestream.Eye(W, H, FPS, report=True)
        for n in range(4):
            t = n / FPS
            gaze = [(t, 30.0, 20.0, 0, 0, 2.5), (t + 0.01, 30.0, 20.0, 0, 0, 3.5)] if n < 3 else []
            dark = scene(n) * 1e-3
            a = recorded.process(dark, gaze)
            b = modelled.process(dark, [g[:3] for g in gaze])
            # The frame's mean; without samples, the last recorded diameter held.
            self.assertAlmostEqual(recorded.report["pupil_mm"], 3.0 if n < 3 else 3.5, places=9)
            self.assertGreater(recorded.report["pupil_model_mm"], 4.0)
            self.assertFalse(np.array_equal(a, b), f"frame {n}")

    def test_errors_carry_the_command_lines_message_and_exit_code(self):
        with self.assertRaises(eyestream.Error) as caught:
            eyestream.Eye(W, H, FPS, viewer_age=500)
        message, code = caught.exception.args
        self.assertIn("--viewer-age", message)
        self.assertEqual(code, 2)
        with self.assertRaises(eyestream.Error) as caught:
            eyestream.Eye(W, H, FPS, no_such_option=1)
        self.assertIn("no-such-option", caught.exception.args[0])
        eye = eyestream.Eye(W, H, FPS)
        with self.assertRaises(eyestream.Error):
            eye.process(np.zeros((H, W + 1, 3), np.float32))
        with self.assertRaises(ValueError):
            eye.process(scene(0), [(0.0, 1.0)])

    def test_keywords_and_docstring_come_from_the_option_table(self):
        table = {p["name"]: p for p in eyestream.parameters()}
        self.assertEqual(table["viewer_age"]["option"], "--viewer-age")
        self.assertEqual(table["viewer_age"]["unit"], "years")
        self.assertIn("viewer_age [years]:", eyestream.Eye.__doc__)
        self.assertEqual(eyestream.parameters("fast") != eyestream.parameters("reference"), True)

    def test_psf_is_cie_146s_equation_at_three_and_ten_degrees(self):
        # CIE 146:2002's general disability glare equation, written out here:
        # the light a pixel sends t degrees away, per steradian of the source.
        def cie(t, age, p):
            return 10 / t**3 + (5 / t**2 + 0.1 * p / t) * (1 + (age / 62.5) ** 4) + 0.0025 * p

        for age in (25, 70):
            out = eyestream.psf(256, 64, adaptation=100.0, psf_model="cie", viewer_age=age,
                                viewer_pigmentation=0.5, flare_lines=False)
            k, ppd = out["kernel"], out["pixels_per_degree"]
            self.assertEqual(k.shape, (127, 511, 3))
            self.assertEqual(k.dtype, np.float32)
            self.assertEqual(np.unravel_index(np.argmax(k[:, :, 1]), k.shape[:2]), (63, 255))
            pixel_sr = (np.pi / 180 / ppd) ** 2
            for t in (1.0, 3.0, 10.0):
                got = k[63, 255 + int(round(t * ppd)), 1] / pixel_sr
                want = cie(round(t * ppd) / ppd, age, 0.5)
                self.assertAlmostEqual(got / want, 1.0, delta=0.02, msg=f"age {age}, {t} deg")
            self.assertGreater(out["pupil_mm"], 1.5)
            # The flare lines move light around each ring, not off it: a
            # ring's mean stays the equation's within 5 %.
            lines = eyestream.psf(256, 64, adaptation=100.0, psf_model="cie", viewer_age=age,
                                  viewer_pigmentation=0.5, flare_lines=True)["kernel"][:, :, 1]
            yy, xx = np.mgrid[0:127, 0:511]
            r = np.hypot(yy - 63, xx - 255) / ppd
            for t in (1.0, 2.0, 3.0):
                ring = (r > t - 0.1) & (r < t + 0.1)
                ratio = (lines[ring] / pixel_sr / cie(r[ring], age, 0.5)).mean()
                self.assertAlmostEqual(ratio, 1.0, delta=0.05, msg=f"flare lines, age {age}, {t} deg")
        with self.assertRaises(eyestream.Error):
            eyestream.psf(0, 10)


if __name__ == "__main__":
    unittest.main()
