"""A loop over frames held in numpy: a 70-year-old viewer at night.

    PYTHONPATH=build/python python3 docs/examples/python_loop.py

A 1e4 cd/m^2 lamp moves across a 0.3 cd/m^2 road for one second at
30 frames/s while the gaze follows it and the eye blinks once; each frame
goes through the eye as it is made, and the script prints what the eye
did. (tests/CMakeLists.txt runs it, so it stays true.)
"""
import numpy as np

import eyestream

WIDTH, HEIGHT, FPS = 320, 180, 30.0

eye = eyestream.Eye(WIDTH, HEIGHT, FPS, quality="fast", viewer_age=70)
road = np.full((HEIGHT, WIDTH, 3), 0.3, np.float32)
for n in range(int(FPS)):
    frame = road.copy()
    lamp_x = 40 + 8 * n
    frame[88:92, lamp_x:lamp_x + 4] = 1e4
    t = n / FPS
    closed = 0.5 <= t < 0.6  # a blink
    gaze = [(t, lamp_x + 2.0, 90.0, closed)]
    shown = eye.process(frame, gaze)  # display-linear, float32 HxWx3
    if n % 10 == 0 or closed:
        r = eye.report
        print(f"frame {n:2d}: adaptation {r['adaptation_cd_m2']:.3g} cd/m^2, pupil {r['pupil_mm']:.2f} mm, "
              f"eye {'closed' if r['eye_closed'] else 'open'}, road beside the lamp {shown[90, lamp_x - 12].mean():.4f}")
print("encoded frame:", eye.code.shape, eye.code.dtype)
