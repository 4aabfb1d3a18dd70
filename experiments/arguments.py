"""Checks of the experiment commands' arguments (paper.py, fidelity.py), as argparse types: a bad
value is an argparse error (exit status 2, the option named, e.g. "argument --res: 'abc' is not
WxH") before anything is built, created or run, rather than a traceback or a sweep whose every
frame fails (issue 39, F15). Standard library only."""
import argparse
import os
import re

# strata-sim refuses frames outside 1..16384 on either side (check_render_settings in
# sim/native_render.cpp); refusing them here saves launching frames that would all fail.
MAX_SIDE = 16384


def side_ok(n):
    return 1 <= n <= MAX_SIDE


def resolution(text):
    """WxH with positive whole numbers, as strata-sim's --res takes it. Returned as
    f"{W}x{H}", so "0128x128" and "128x128" are one frame, not two runs of the same one."""
    m = re.fullmatch(r"([0-9]+)x([0-9]+)", text)  # digits only: int() would take " 1", "+1", "1_0"
    if not m:
        raise argparse.ArgumentTypeError(f"'{text}' is not WxH (for example 128x128)")
    w, h = int(m[1]), int(m[2])
    if not (side_ok(w) and side_ok(h)):
        raise argparse.ArgumentTypeError(f"'{text}': width and height must be 1..{MAX_SIDE}")
    return f"{w}x{h}"


def positive_int(text):
    """A count of frames at once: 0 or less is refused, not taken as "all cores" (that is the
    default, when the option is not given)."""
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a whole number")
    if n < 1:
        raise argparse.ArgumentTypeError(f"must be 1 or more, got {n}")
    return n


def output_folder(text):
    """A folder that exists, or can be made: the path must not be, or lie under, something
    other than a folder, and the nearest existing folder must be writable. Checked without
    creating anything, so a refused command leaves no folders behind."""
    if not text:
        raise argparse.ArgumentTypeError("an empty path")
    probe = os.path.abspath(text)
    while not os.path.lexists(probe):  # the nearest part of the path that exists ("/" does)
        probe = os.path.dirname(probe)
    if not os.path.isdir(probe):
        raise argparse.ArgumentTypeError(f"'{text}' exists and is not a folder" if probe == os.path.abspath(text)
                                         else f"'{text}': {probe} is not a folder")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise argparse.ArgumentTypeError(f"'{text}': the folder {probe} is not writable")
    return text


def target_error(text):
    """A relative 95% half-width for sampled timing's error target, as strata-sim takes
    timing.sample_target_error (0.001..0.5; 0, "off", is the option left out)."""
    try:
        e = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number")
    if not 0.001 <= e <= 0.5:
        raise argparse.ArgumentTypeError(f"must be 0.001..0.5 (a relative half-width, e.g. 0.02), got {text}")
    return e


def name_list(text):
    """Comma-separated names (empty entries, e.g. of a trailing comma, dropped): at least one,
    none twice (a name listed twice would be the same frames twice, run once)."""
    names = [s for s in text.split(",") if s]
    if not names:
        raise argparse.ArgumentTypeError(f"'{text}' names none")
    for i, s in enumerate(names):
        if s in names[:i]:
            raise argparse.ArgumentTypeError(f"'{s}' is listed twice")
    return names
