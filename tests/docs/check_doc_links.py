#!/usr/bin/env python3
"""Checks that every link and citation of the documentation resolves inside
the repository (issue 34, "links resolve").

1. Markdown links. A link `[text](target)` or image `![alt](target)` in a
   Markdown file points to a file or folder of the tree (relative to the
   Markdown file), and its `#anchor`, if any, to a heading or an explicit
   anchor (`<a id="...">`) of the target Markdown file. Headings get
   GitHub's slugs: lower case, inline code and link syntax reduced to their
   text, every character but letters, digits, `_`, `-` and spaces dropped,
   spaces turned into `-`, repeated slugs suffixed `-1`, `-2`, ...
   Links to web addresses are not followed.
2. Citations by section. In every text file of the tree (code comments,
   docs, scripts, configs, tests), a document cited with a section,
     <doc>.md 3.3   <doc>.md §1.4-1.5   <doc>.md section 12   <doc>.md 3.1, 3.5, 6
     <doc>.md (i)   <doc>.md (e)-(g)    <doc>.md "Title"      <doc>.md, "Title"
   (also across the line break and comment marks of a comment, and across
   the pieces of a C++ string literal), must be a Markdown file of the tree
   that has that section: a heading numbered "3.3" or "12." (`## 12. Flow`,
   `### 3.3 Steady network balance`), a heading starting with "(i)", or, for
   a quoted title, a heading containing it (case-insensitive, `_` read as a
   space) or else that text somewhere in the document (a table's or a
   paragraph's name). <doc>.md without a folder is looked up next to the
   citing file, then in docs/, then at the top of the tree.
3. Paths outside the repository: no text file names the shared folder
   beside the repository or the development machine's work folder (also
   when a string literal is split inside the name), and no Markdown link's
   target climbs above the tree.

Usage: check_doc_links.py ROOT [--exclude PATH]...
  ROOT: the tree to check; its files are `git ls-files` when ROOT is the top
  of a git work tree, else every file below it. --exclude leaves out a
  folder (relative to ROOT): the broken fixture of the second test.
Prints one line per defect, "FILE:LINE: what", then a count; exit status 1
when there is a defect.
"""
import argparse
import pathlib
import re
import subprocess
import sys

# ---- the files ---------------------------------------------------------------

BINARY_SUFFIXES = {
    ".png", ".jpg", ".jpeg", ".gif", ".pdf", ".h5", ".hdf5", ".gz", ".zip",
    ".xz", ".bin", ".npz", ".npy", ".ico", ".svg",
}


def generated(parts):
    """Whether a path (its parts below the root) is git's, a build's or a run's."""
    return ".git" in parts or parts[0].startswith("build") or parts[0] == "out"


def tree_files(root, excluded):
    """Paths relative to root (POSIX strings) of the files to check."""
    names = None
    if (root / ".git").exists():
        try:
            out = subprocess.run(["git", "-C", str(root), "ls-files", "-z"],
                                 capture_output=True, check=True).stdout
            names = [n for n in out.decode().split("\0") if n]
        except (OSError, subprocess.CalledProcessError):
            names = None
    if names is None:  # not a git work tree: every file but build and run output
        names = [p.relative_to(root).as_posix() for p in sorted(root.rglob("*"))
                 if p.is_file() and not generated(p.relative_to(root).parts)]
    keep = []
    for n in names:
        if any(n == e or n.startswith(e.rstrip("/") + "/") for e in excluded):
            continue
        keep.append(n)
    return keep


def read_text(path):
    """The file's text, or None for a binary or unreadable file."""
    if path.suffix.lower() in BINARY_SUFFIXES:
        return None
    try:
        data = path.read_bytes()
    except OSError:
        return None
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


# ---- Markdown structure -------------------------------------------------------

FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
EXPLICIT_ANCHOR = re.compile(r"""<a\s+(?:[^>]*\s)?(?:id|name)\s*=\s*["']([^"']+)["']""", re.I)
INLINE_CODE = re.compile(r"`+[^`]*`+")
MD_LINK_TEXT = re.compile(r"!?\[([^\]]*)\]\([^)]*\)")
HTML_TAG = re.compile(r"<[^>]+>")
# A section number at the start of a heading: "3.", "3.3", "12."
SECTION_NUMBER = re.compile(r"^(\d+(?:\.\d+)*)\.?(?=\s|$)")
SECTION_LETTER = re.compile(r"^\(([a-z])\)\s")


def slug(text):
    """GitHub's heading slug (github-slugger)."""
    text = MD_LINK_TEXT.sub(r"\1", text)
    text = HTML_TAG.sub("", text)
    text = text.replace("`", "")
    text = text.lower()
    text = "".join(c for c in text if c.isalnum() or c in "_- ")
    return text.replace(" ", "-")


def normal_title(text):
    """Lower case, without backticks, `_` and runs of white space as one space."""
    return " ".join(text.lower().replace("`", "").replace("_", " ").split())


def markdown_lines(text):
    """(line number, line) of a Markdown text outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


class Document:
    """What a Markdown file defines: anchors, section numbers, letters, titles."""

    def __init__(self, text):
        self.text = normal_title(text)
        self.anchors = set()
        self.sections = set()
        self.letters = set()
        self.titles = []
        seen = {}
        for _, line in markdown_lines(text):
            for a in EXPLICIT_ANCHOR.findall(line):
                self.anchors.add(a)
            m = HEADING.match(line)
            if not m:
                continue
            title = m.group(2)
            base = slug(title)
            n = seen.get(base, 0)
            seen[base] = n + 1
            self.anchors.add(base if n == 0 else f"{base}-{n}")
            plain = HTML_TAG.sub("", MD_LINK_TEXT.sub(r"\1", title)).replace("`", "").strip()
            self.titles.append(normal_title(plain))
            if number := SECTION_NUMBER.match(plain):
                self.sections.add(number.group(1))
            if letter := SECTION_LETTER.match(plain):
                self.letters.add(letter.group(1))


# ---- citations ----------------------------------------------------------------

# Comment marks at the start of a line: a citation may continue on the next
# line of a comment.
LINE_PREFIX = re.compile(r"^\s*(?://+!?|/\*+|\*+(?!\*)|#+|--|;+|\"\"\"|''')?\s?")
NUM = r"\d+(?:\.\d+)*"
NUM_LIST = rf"{NUM}(?:\s*(?:[-–]|,|\band\b|\bto\b)\s*{NUM}\b(?!\.\d))*"
LETTER = r"\([a-z]\)"
LETTER_LIST = rf"{LETTER}(?:\s*(?:[-–]|,|\band\b)\s*{LETTER})*"
DOC = r"(?<![\w./-])((?:\.\.?/)*(?:[\w-]+/)*[A-Za-z][\w-]*\.md)"
CITATION = re.compile(
    DOC + r",?\s+(?:"
    rf"(?:(?:sections?|§)\s*)?(?P<numbers>{NUM_LIST})(?![\w/])"
    rf"|(?P<letters>{LETTER_LIST})"
    r"|(?:section\s+)?[\"“](?P<title>[^\"”\n]{0,80}\w[^\"”\n]{0,80})[\"”]"
    r")")
# The shared folder beside the repository (also named without its "../", as
# its docs/ and seeds/ folders), and the development machine's work folder
# (written in pieces so that this file does not name them).
OUTSIDE = re.compile("(" + re.escape("..") + "/shared\\b|\\bsha" + "red/(?:docs|seeds)/|/wor" + "k/)")
MARKDOWN_LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_DEFINITION = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
WEB = re.compile(r"^(?:[a-z][a-z0-9+.-]*:|//)", re.I)


# The pieces of a C++ string literal split over lines ("... " "...") or on
# one line, and its escaped quotes.
STRING_JOIN = re.compile(r'"[ \t]*$')
STRING_START = re.compile(r'^\s*"')
STRING_PIECES = re.compile(r'(?<=\S)"[ \t]+"(?=\S)')


def joined(text, code):
    """The text with each line's leading comment marks dropped and the lines
    joined by spaces, and (offset, line number) where each line starts in it.
    In code (`code`), the pieces of a string literal are joined without a
    space and its escaped quotes unescaped."""
    raw = text.split("\n")
    pieces, lines, offset = [], [], 0
    glue = False  # the previous line ended in a string literal that goes on
    for number, line in enumerate(raw, 1):
        if code:
            line = STRING_PIECES.sub("", line.replace('\\"', '"'))
        line = (STRING_START if glue else LINE_PREFIX).sub("", line, count=1)
        separator = "" if glue or not pieces else " "
        glue = (code and number < len(raw) and STRING_JOIN.search(line) is not None
                and STRING_START.match(raw[number]) is not None)
        if glue:
            line = STRING_JOIN.sub("", line)
        offset += len(separator)
        lines.append((offset, number))
        pieces.append(separator + line)
        offset += len(line)
    return "".join(pieces), lines


def line_of(offset, lines):
    lo, hi = 0, len(lines) - 1
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if lines[mid][0] <= offset:
            lo = mid
        else:
            hi = mid - 1
    return lines[lo][1]


def expand_numbers(text):
    """'1.4-1.5' -> ['1.4', '1.5']; '3.1, 3.5, 6' -> ['3.1', '3.5', '6']."""
    return re.findall(NUM, text)


class Checker:
    def __init__(self, root, files):
        self.root = root
        self.files = set(files)
        self.folders = {str(pathlib.PurePosixPath(f).parent) for f in files}
        for f in list(self.folders):
            p = pathlib.PurePosixPath(f)
            while str(p) not in ("", "."):
                self.folders.add(str(p))
                p = p.parent
        self.documents = {}
        self.defects = []
        self.counts = {"links": 0, "citations": 0}

    def document(self, relative):
        if relative not in self.documents:
            text = read_text(self.root / relative) or ""
            self.documents[relative] = Document(text)
        return self.documents[relative]

    def report(self, where, line, what):
        self.defects.append(f"{where}:{line}: {what}")

    def normalize(self, base, target):
        """target relative to folder base, as a tree path; None above the tree."""
        parts = []
        for part in (pathlib.PurePosixPath(base) / target).parts:
            if part in ("", "."):
                continue
            if part == "..":
                if not parts:
                    return None
                parts.pop()
            else:
                parts.append(part)
        return "/".join(parts)

    def exists(self, relative):
        return relative in self.files or relative in self.folders or relative == ""

    def resolve_cited(self, citing, name):
        """The tree path of a cited NAME.md, or None."""
        folder = str(pathlib.PurePosixPath(citing).parent)
        candidates = [self.normalize(folder, name)]
        if "/" not in name:
            candidates += [f"docs/{name}", name]
        else:
            candidates.append(self.normalize("", name))
        for c in candidates:
            if c is not None and c in self.files:
                return c
        return None

    # -- 1. Markdown links
    def check_links(self, relative, text):
        folder = str(pathlib.PurePosixPath(relative).parent)
        for number, line in markdown_lines(text):
            line = INLINE_CODE.sub("", line)
            targets = MARKDOWN_LINK.findall(line)
            if m := REFERENCE_DEFINITION.match(line):
                targets.append(m.group(1))
            for target in targets:
                if WEB.match(target):
                    continue
                self.counts["links"] += 1
                path, _, anchor = target.partition("#")
                if path:
                    resolved = self.normalize(folder, path)
                    if resolved is None:
                        self.report(relative, number,
                                    f"link '{target}' points outside the repository")
                        continue
                    if not self.exists(resolved):
                        self.report(relative, number,
                                    f"link '{target}': no file {resolved} in the repository")
                        continue
                else:
                    resolved = relative
                if anchor and resolved.endswith(".md"):
                    if anchor not in self.document(resolved).anchors:
                        self.report(relative, number,
                                    f"link '{target}': {resolved} has no heading or anchor "
                                    f"'#{anchor}'")

    # -- 2. citations by section
    def check_citations(self, relative, text):
        flat, lines = joined(text, not relative.endswith(".md"))
        for m in CITATION.finditer(flat):
            name = m.group(1)
            number = line_of(m.start(), lines)
            self.counts["citations"] += 1
            cited = self.resolve_cited(relative, name)
            quoted = m.group(0).strip()
            if cited is None:
                self.report(relative, number,
                            f"'{quoted}' cites {name}, which is not in the repository")
                continue
            doc = self.document(cited)
            if m.group("numbers"):
                for n in expand_numbers(m.group("numbers")):
                    if n not in doc.sections:
                        self.report(relative, number,
                                    f"'{quoted}': {cited} has no section {n}")
            elif m.group("letters"):
                for letter in re.findall(r"\(([a-z])\)", m.group("letters")):
                    if letter not in doc.letters:
                        self.report(relative, number,
                                    f"'{quoted}': {cited} has no section ({letter})")
            else:
                title = normal_title(m.group("title"))
                if not any(title in t for t in doc.titles) and title not in doc.text:
                    self.report(relative, number,
                                f"'{quoted}': {cited} has no section titled '{m.group('title')}'")

    # -- 3. paths outside the repository
    def check_outside(self, relative, text):
        found = set()
        for number, line in enumerate(text.split("\n"), 1):
            for m in OUTSIDE.finditer(line):
                found.add((number, m.group(1)))
        if not relative.endswith(".md"):  # ... and in string literals split inside the name
            flat, lines = joined(text, True)
            for m in OUTSIDE.finditer(flat):
                found.add((line_of(m.start(), lines), m.group(1)))
        for number, name in sorted(found):
            self.report(relative, number, f"names '{name}', a path outside the repository")

    def run(self, files):
        for relative in sorted(files):
            text = read_text(self.root / relative)
            if text is None:
                continue
            if relative.endswith(".md"):
                self.check_links(relative, text)
            self.check_citations(relative, text)
            self.check_outside(relative, text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root", type=pathlib.Path)
    parser.add_argument("--exclude", action="append", default=[])
    parser.add_argument("--list", action="store_true",
                        help="also print every citation found (for review)")
    args = parser.parse_args()
    root = args.root.resolve()
    files = tree_files(root, args.exclude)
    checker = Checker(root, files)
    checker.run(files)
    for d in checker.defects:
        print(d)
    print(f"check_doc_links: {len(files)} files, {checker.counts['links']} links, "
          f"{checker.counts['citations']} citations, {len(checker.defects)} defects")
    return 1 if checker.defects else 0


if __name__ == "__main__":
    sys.exit(main())
