"""Scenes for the run.py drivers: a configs/ file with some of its text
replaced. A replaced text that the file no longer holds stops the driver
with its name (the benchmark would otherwise measure another scene)."""
import sys


def edited(source, replacements):
    """The text of `source` (a pathlib.Path) with each (old, new) of
    `replacements` applied in turn."""
    text = source.read_text()
    for old, new in replacements:
        if old not in text:
            sys.exit(f"{sys.argv[0]}: {source} no longer holds {old!r}")
        text = text.replace(old, new)
    return text
