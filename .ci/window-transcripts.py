#!/usr/bin/env python3
"""Run the pages' transcripts that open a window (demo ... --frames), which JUnit cannot
(it never has a display), and compare what they print with the page, by the rules of
src/test/java/particlelab/app/TranscriptTest.java: a line '...' stands for any lines, and
'<measured>' for one measured figure (any run of non-space characters).

Usage: window-transcripts.py APP  (the installed start script; run under a display)."""
import glob
import os
import re
import shlex
import subprocess
import sys

PROMPT = "$ particle-lab "
MEASURED = "<measured>"


def transcripts():
    pages = ["README.md"] + sorted(glob.glob("docs/**/*.md", recursive=True))
    for page in pages:
        fenced, current = False, None
        with open(page, encoding="utf-8") as text:
            lines = text.read().splitlines()
        for number, line in enumerate(lines, 1):
            if line.startswith("```"):
                fenced = not fenced
                if current:
                    yield current
                current = None
            elif fenced and line.startswith(PROMPT):
                if current:
                    yield current
                current = (page, number, line[2:], [])
            elif fenced and current:
                current[3].append(line)
        if current:
            yield current


def opens_window(command):
    words = command.split()
    return len(words) > 1 and words[1] == "demo" and "--frames" in words


def line_matches(expected, actual):
    if MEASURED not in expected:
        return expected == actual
    pattern = r"\S+".join(re.escape(part) for part in expected.split(MEASURED))
    return re.fullmatch(pattern, actual) is not None


def matches(expected, actual):
    if not expected:
        return not actual
    if expected[0] == "...":
        return any(matches(expected[1:], actual[skip:]) for skip in range(len(actual) + 1))
    return bool(actual) and line_matches(expected[0], actual[0]) and matches(expected[1:],
                                                                           actual[1:])


def main():
    app = sys.argv[1]
    failed = checked = 0
    for page, number, command, expected in transcripts():
        if not opens_window(command):
            continue
        while expected and not expected[-1].strip():
            expected.pop()
        words = shlex.split(command)[1:]
        if "--screenshot" in words:
            # The page's example writes a new file; a run before this one may have left it.
            target = words[words.index("--screenshot") + 1]
            if os.path.isfile(target) and not os.path.islink(target):
                os.remove(target)
        run = subprocess.run([app] + words, capture_output=True, text=True, timeout=300)
        actual = (run.stdout + run.stderr).splitlines()
        checked += 1
        if run.returncode != 0 or not matches(expected, actual):
            failed += 1
            print(f"window-transcripts: {page}:{number} $ {command}\n  prints:\n    "
                  + "\n    ".join(actual) + "\n  but the page shows:\n    "
                  + "\n    ".join(expected), file=sys.stderr)
    print(f"window-transcripts: {checked} checked, {failed} differ from their page")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
