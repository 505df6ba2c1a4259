#!/usr/bin/env python3
"""Checks that the README shows what the repository has (CTest case test_readme).

  test_readme.py [SOURCE_DIR]          checks SOURCE_DIR/README.md (default: this repository)
  test_readme.py --readme FILE [SOURCE_DIR]   checks FILE against SOURCE_DIR

- A code block preceded by the line `<!-- example: PATH -->` is the file PATH, an example
  program under examples/ that CTest runs, or a contiguous run of its lines, character for
  character. Every ```cpp and ```python block must carry such a line: the README shows no
  code that no test runs.
- Every image it shows (![...](PATH) or <img src="PATH">) is a file of the repository, and a
  PNG, JPEG or SVG.
- Every link to a file of the repository names a file that exists; a link to
  doc/Heat_diffusion/Heat_diffusion.txt#ID names a \\section, \\subsection or \\anchor ID of
  the manual.
- A table with a column "printed by" names in each row a program of benchmark/Heat_diffusion/.
- At most MAX_LINES lines, and no table cell longer than MAX_CELL characters.

Each problem is printed with its line number; the exit status is 1 if there is one. Before
checking the README, the script checks itself: copies of the README with a code line
changed, an image renamed, a manual section renamed and an unmarked C++ block must fail.
Python 3 standard library only.
"""
import bisect
import os
import re
import sys
import tempfile

MAX_LINES = 150
MAX_CELL = 100
EXAMPLE_MARK = re.compile(r"^<!--\s*example:\s*(\S+)\s*-->\s*$")
FENCE = re.compile(r"^(```+|~~~+)\s*([\w+-]*)\s*$")
CODE_LANGUAGES = {"cpp", "c++", "cxx", "python", "py"}
MARKDOWN_IMAGE = re.compile(r"!\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML_IMAGE = re.compile(r"<img\b[^>]*\bsrc\s*=\s*[\"']([^\"']+)[\"']", re.IGNORECASE)
LINK = re.compile(r"(?<!!)\[[^\]]*\]\(\s*<?([^)\s>]+)>?\s*\)")
MANUAL = "doc/Heat_diffusion/Heat_diffusion.txt"
IMAGE_SIGNATURES = {".png": b"\x89PNG\r\n\x1a\n", ".jpg": b"\xff\xd8", ".jpeg": b"\xff\xd8"}


def read_lines(path):
    with open(path, encoding="utf-8") as fh:
        return fh.read().split("\n")


def code_blocks(lines):
    """(first line number, language, lines, the example PATH it claims or None, marker line)."""
    blocks, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, language = m.group(1), m.group(2).lower()
        j = i + 1
        while j < len(lines) and not lines[j].startswith(fence[0] * len(fence)):
            j += 1
        k = i - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        mark = EXAMPLE_MARK.match(lines[k]) if k >= 0 else None
        blocks.append((i + 1, language, lines[i + 1:j], mark.group(1) if mark else None, k + 1))
        i = j + 1
    return blocks


def outside_code(lines):
    """(line number, text) of the lines that are not inside a code block."""
    inside, out = None, []
    for n, line in enumerate(lines, 1):
        m = FENCE.match(line)
        if inside is None and m:
            inside = m.group(1)
            continue
        if inside is not None:
            if line.startswith(inside[0] * len(inside)):
                inside = None
            continue
        out.append((n, line))
    return out


def local_target(target):
    """The repository path a link or image names, or None for a URL or an anchor."""
    if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE) or target.startswith("#"):
        return None
    return target.split("#", 1)[0].split("?", 1)[0]


def manual_ids(root):
    path = os.path.join(root, MANUAL)
    if not os.path.isfile(path):
        return set()
    ids = set()
    for line in read_lines(path):
        m = re.match(r"^\s*\\(?:section|subsection|subsubsection|anchor|page)\s+(\w+)", line)
        if m:
            ids.add(m.group(1))
    return ids


def table_rows(text_lines):
    """Tables as lists of (line number, cells), the header first (separator rows dropped)."""
    tables, current = [], []
    for n, line in text_lines:
        if line.lstrip().startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not all(re.fullmatch(r":?-+:?", c) for c in cells):
                current.append((n, cells))
        elif current:
            tables.append(current)
            current = []
    if current:
        tables.append(current)
    return tables


def check(readme, root):
    problems = []
    say = problems.append
    lines = read_lines(readme)
    if lines and lines[-1] == "":
        lines = lines[:-1]
    if len(lines) > MAX_LINES:
        say(f"{len(lines)} lines, more than {MAX_LINES}")

    # Code blocks and the example programs they come from.
    languages_shown = set()
    for first, language, block, claimed, mark_line in code_blocks(lines):
        if claimed is None:
            if language in CODE_LANGUAGES:
                say(f"line {first}: a {language} block without '<!-- example: PATH -->' before it "
                    "(the README's code is an example program that CTest runs)")
            continue
        norm = os.path.normpath(claimed)
        if norm.startswith("..") or os.path.isabs(norm) or not norm.startswith("examples" + os.sep):
            say(f"line {mark_line}: {claimed} is not a file under examples/")
            continue
        path = os.path.join(root, norm)
        if not os.path.isfile(path):
            say(f"line {mark_line}: the example {claimed} does not exist")
            continue
        if not block or not any(l.strip() for l in block):
            say(f"line {first}: the block from {claimed} is empty")
            continue
        source = read_lines(path)
        n = len(block)
        if not any(source[s:s + n] == block for s in range(len(source) - n + 1)):
            # name the first line that differs from the best match, to help the fix
            best, at = 0, 0
            for s in range(len(source)):
                k = 0
                while k < n and s + k < len(source) and source[s + k] == block[k]:
                    k += 1
                if k > best:
                    best, at = k, s
            if best == 0:
                detail = f"its first line is not a line of the file: {block[0]!r}"
            elif best < n:
                detail = (f"its line {first + 1 + best} differs from line {at + 1 + best} of the file: "
                          f"{block[best]!r} against {source[at + best] if at + best < len(source) else '(end of file)'!r}")
            else:
                detail = "it runs past the end of the file"
            say(f"line {first}: the block is not {claimed} nor a contiguous part of it: {detail}")
            continue
        languages_shown.add("python" if language in ("python", "py") else
                            "cpp" if language in ("cpp", "c++", "cxx") else language)
    for language in ("cpp", "python"):
        if language not in languages_shown:
            say(f"no {language} example block (a C++ and a Python example program are expected)")

    # Images, links, tables (outside code blocks).
    text = outside_code(lines)
    # links and images may wrap: search the text outside code blocks as one string
    joined, starts = "", []
    for n, line in text:
        starts.append((len(joined), n))
        joined += line + "\n"
    offsets = [o for o, _ in starts]

    def line_of(pos):
        return starts[bisect.bisect_right(offsets, pos) - 1][1]

    ids = manual_ids(root)
    images = 0
    image_spans = []
    for m in list(MARKDOWN_IMAGE.finditer(joined)) + list(HTML_IMAGE.finditer(joined)):
        images += 1
        image_spans.append(m.span())
        n, target = line_of(m.start()), m.group(1)
        path = local_target(target)
        if path is None:
            say(f"line {n}: the image {target} is not a file of the repository")
            continue
        full = os.path.join(root, path)  # paths are relative to the README, at the top
        if not os.path.isfile(full):
            say(f"line {n}: the image {path} does not exist")
            continue
        ext = os.path.splitext(path)[1].lower()
        with open(full, "rb") as fh:
            head = fh.read(512)
        if ext in IMAGE_SIGNATURES and not head.startswith(IMAGE_SIGNATURES[ext]):
            say(f"line {n}: the image {path} is not a {ext[1:].upper()} file")
        elif ext == ".svg" and b"<svg" not in head and b"<?xml" not in head:
            say(f"line {n}: the image {path} is not an SVG file")
        elif ext not in IMAGE_SIGNATURES and ext != ".svg":
            say(f"line {n}: the image {path} is not a PNG, JPEG or SVG file")
    for m in LINK.finditer(joined):
        if any(a <= m.start() < b for a, b in image_spans):
            continue
        n, target = line_of(m.start()), m.group(1)
        path = local_target(target)
        if path is None:
            continue
        if not os.path.exists(os.path.join(root, path)):
            say(f"line {n}: the link {target} names no file of the repository")
        elif os.path.normpath(path) == os.path.normpath(MANUAL) and "#" in target:
            anchor = target.split("#", 1)[1]
            if anchor not in ids:
                say(f"line {n}: the manual has no section {anchor} ({MANUAL})")
    if images == 0:
        say("no image: the README starts with the overview figure")

    benchmark_dir = os.path.join(root, "benchmark", "Heat_diffusion")
    for table in table_rows(text):
        for n, cells in table:
            for cell in cells:
                if len(cell) > MAX_CELL:
                    say(f"line {n}: a table cell of {len(cell)} characters, more than {MAX_CELL}: {cell[:40]}...")
        header = [c.lower() for c in table[0][1]]
        if "printed by" in header:
            column = header.index("printed by")
            for n, cells in table[1:]:
                m = re.match(r"^`([\w.]+)", cells[column]) if column < len(cells) else None
                names = [m.group(1)] if m else []
                if not m or not any(os.path.isfile(os.path.join(benchmark_dir, name + ext))
                                    for name in names for ext in ("", ".cpp", ".py", ".sh")):
                    say(f"line {n}: the figure's command is not a program of benchmark/Heat_diffusion/: "
                        f"{cells[column] if column < len(cells) else '(none)'}")
    return problems


def self_test(readme, root):
    """The check must fail on broken copies of the README; returns the failures to fail."""
    original = "\n".join(read_lines(readme))
    lines = original.split("\n")
    blocks = [b for b in code_blocks(lines) if b[3]]
    mutations = []
    if blocks:
        first, _, block, _, _ = blocks[0]
        k = next(i for i, l in enumerate(block) if l.strip())
        changed = list(lines)
        changed[first + k] = changed[first + k].rstrip() + " // changed"
        mutations.append(("a code line changed", "\n".join(changed)))
        unmarked = list(lines)
        del unmarked[blocks[0][4] - 1]
        mutations.append(("an example block without its mark", "\n".join(unmarked)))
    image = re.search(r"!\[[^\]]*\]\(([^)\s]+)\)", original)
    if image:
        mutations.append(("an image that does not exist",
                          original.replace(image.group(1), image.group(1) + ".missing.png", 1)))
    anchor = re.search(re.escape(MANUAL) + r"#(\w+)", original)
    if anchor:
        mutations.append(("a manual section that does not exist",
                          original.replace(anchor.group(0), MANUAL + "#no_such_section", 1)))
    mutations.append(("an unmarked C++ block", original + "\n```cpp\nint main() {}\n```\n"))
    failures = []
    with tempfile.TemporaryDirectory() as work:
        for name, text in mutations:
            copy = os.path.join(work, "README.md")
            with open(copy, "w", encoding="utf-8") as fh:
                fh.write(text)
            if not check(copy, root):
                failures.append(f"self-test: the check passes a README with {name}")
    if len(mutations) < 5:
        failures.append("self-test: the README has no example block, image or manual link to break")
    return failures


def main(argv):
    args = list(argv[1:])
    readme = None
    if args[:1] == ["--readme"]:
        if len(args) < 2:
            print("usage: test_readme.py [--readme FILE] [SOURCE_DIR]", file=sys.stderr)
            return 2
        readme, args = args[1], args[2:]
    if len(args) > 1 or any(a.startswith("-") for a in args):
        print("usage: test_readme.py [--readme FILE] [SOURCE_DIR]", file=sys.stderr)
        return 2
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    readme = os.path.abspath(readme or os.path.join(root, "README.md"))
    if not os.path.isfile(readme):
        print(f"test_readme.py: {readme} does not exist", file=sys.stderr)
        return 1
    problems = self_test(readme, root) + check(readme, root)
    for p in problems:
        print(f"{os.path.relpath(readme)}: {p}" if not p.startswith("self-test") else p)
    if problems:
        return 1
    print(f"{os.path.relpath(readme)}: the code blocks are the examples', the images and links exist")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
