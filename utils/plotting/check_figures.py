#!/usr/bin/python3
"""Checks that figures were drawn and are not trivial: each named PNG exists, is at least
--min-bytes large, at least 300 x 200 pixels, and not blank (a visible share of its pixels
differs from the background and the pixel values vary).

Usage: check_figures.py FOLDER NAME.png [NAME.png ...]
Exit status 0 when every figure passes; otherwise each failure is printed.
"""
import argparse
import os
import sys

import numpy as np


def check(path, min_bytes):
    """The list of problems of one PNG (empty when it passes)."""
    import matplotlib.image as mpimg
    if not os.path.isfile(path):
        return ["missing"]
    problems = []
    size = os.path.getsize(path)
    if size < min_bytes:
        problems.append(f"{size} bytes, fewer than {min_bytes}")
    try:
        image = mpimg.imread(path)
    except (OSError, ValueError, SyntaxError) as error:
        return problems + [f"not a readable PNG ({error})"]
    height, width = image.shape[:2]
    if width < 300 or height < 200:
        problems.append(f"{width} x {height} pixels, smaller than 300 x 200")
    rgb = image[:, :, :3] if image.ndim == 3 else image[:, :, None]
    background = np.median(rgb.reshape(-1, rgb.shape[-1]), axis=0)
    # A pixel is drawn on when it differs from the background by more than 5% in any channel
    # (anti-aliasing makes faint edges; 5% ignores them). An empty canvas inks 0%; a figure
    # with axes, labels and curves several percent. Empty axes with tick labels ink more
    # than 1% too: the file size catches those (below).
    inked = np.abs(rgb - background).max(axis=-1) > 0.05
    share = inked.mean()
    if share < 0.01:
        problems.append(f"blank: only {100 * share:.2f}% of the pixels differ from the background")
    if float(rgb.std()) < 0.02:
        problems.append(f"blank: pixel standard deviation {rgb.std():.4f}")
    return problems


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("names", nargs="+")
    parser.add_argument("--min-bytes", type=int, default=10000,
                        help="smallest acceptable file (default 10000: measured, an empty 600 x 400 "
                             "canvas is 2 kB, one empty axes with ticks 7.5 kB, one axes with a line 16 kB)")
    args = parser.parse_args(argv)
    failures = 0
    for name in args.names:
        problems = check(os.path.join(args.folder, name), args.min_bytes)
        if problems:
            failures += 1
            print(f"FAIL {name}: {'; '.join(problems)}")
        else:
            print(f"ok   {name}")
    print(f"{len(args.names) - failures} of {len(args.names)} figures pass")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
