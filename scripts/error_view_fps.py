"""Measures the window's frame rate with the error view on and off (docs/tuning.md, "The error in
the window"): `clothlab view SCENE` under a virtual display (xvfb-run, so Mesa's llvmpipe draws)
for a number of frames, the error view turned on by its key on the second frame or left off,
in alternating rounds; prints a Markdown table of the median frame time, the frame rate, the
share of real time simulated and, with the view on, the comparisons made and the frames the
shown run waited for the reference.

    /usr/bin/python3 scripts/error_view_fps.py [--scene scenes/default.toml] [--frames 300]
        [--rounds 3] [--size 1280x800] [--binary build/release/apps/clothlab]
"""
import argparse
import os
import pathlib
import re
import statistics
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[1]
FRAMES = re.compile(r"(\d+) frames: ([0-9.]+) ms/frame, .* (\d+) % of real time simulated")
SUMMARY = re.compile(r"error view: (\d+) comparisons .* waited in (\d+) of (\d+) frames")


def run(binary, scene, frames, size, error_view):
    env = dict(os.environ, CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=str(frames))
    env.pop("WAYLAND_DISPLAY", None)
    if error_view:
        env["CLOTHLAB_VIEW_KEYS"] = ",E"
    out = subprocess.run(
        ["xvfb-run", "-a", "-s", f"-screen 0 {size}x24", binary, "view", scene],
        env=env, capture_output=True, text=True, check=True).stdout
    m = FRAMES.search(out)
    if not m:
        raise RuntimeError("no frame summary in:\n" + out)
    s = SUMMARY.search(out)
    return {
        "ms": float(m.group(2)),
        "real_time": int(m.group(3)),
        "comparisons": int(s.group(1)) if s else None,
        "waited": f"{s.group(2)} of {s.group(3)}" if s else "",
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes/default.toml"))
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--size", default="1280x800")
    parser.add_argument("--binary", default=str(ROOT / "build/release/apps/clothlab"))
    args = parser.parse_args()
    results = {False: [], True: []}
    for _ in range(args.rounds):
        for on in (False, True):
            results[on].append(run(args.binary, args.scene, args.frames, args.size, on))
    print(f"{pathlib.Path(args.scene).name}, {args.size}, {args.frames} frames, "
          f"median of {args.rounds} rounds")
    print("| error view | ms/frame | frames/s | % of real time | comparisons | waited (frames) |")
    print("| --- | --- | --- | --- | --- | --- |")
    for on in (False, True):
        rounds = results[on]
        ms = statistics.median(r["ms"] for r in rounds)
        best = min(rounds, key=lambda r: abs(r["ms"] - ms))
        print(f"| {'on' if on else 'off'} | {ms:.1f} | {1e3 / ms:.1f} | {best['real_time']} | "
              f"{best['comparisons'] if on else ''} | {best['waited']} |")


if __name__ == "__main__":
    main()
