#!/usr/bin/python3
"""The README and docs/ point only at what exists.

  doc_links.py SOURCE_DIR

Checks README.md and every docs/**/*.md and prints one line per finding, named by its rule:
  broken-link     a relative link [text](path) whose file or folder does not exist
  broken-anchor   a link's #anchor that names no heading of its page
  unknown-command `./sdlqr WORD` where WORD is no command of ./sdlqr's main()
  missing-file    an inline `path/...` into a folder of the repository that does not exist
  unknown-executable  `sdlqr-NAME` that no CMakeLists.txt or cmake/ file names (an executable)
Exit 0 without a finding, 1 with one, 2 on bad input.
"""
import os
import re
import subprocess
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
SDLQR = re.compile(r"\./sdlqr\s+([a-z][\w-]*|--?[\w-]+)")
INLINE = re.compile(r"`([^`\n]+)`")
# An executable's name as prose or a command line spells it (not inside a path or a longer word).
EXECUTABLE = re.compile(r"(?<![\w/.-])sdlqr-[a-z][a-z0-9]*(?:-[a-z0-9]+)*")
# A path a reader would type: no placeholder, glob, variable or elision.
NOT_LITERAL = re.compile(r"[<>*{}$|]|\.\.\.|…")


def repository_entries(root):
    """Top-level names and every path of the repository (git's index, else the folder)."""
    files = []
    try:
        top = subprocess.run(["git", "-C", root, "rev-parse", "--show-toplevel"], check=True, capture_output=True,
                             text=True).stdout.strip()
        if os.path.realpath(top) == os.path.realpath(root):  # not a folder inside another repository
            files = subprocess.run(["git", "-C", root, "ls-files"], check=True, capture_output=True,
                                   text=True).stdout.split()
    except (subprocess.CalledProcessError, FileNotFoundError):
        pass
    if not files:
        for folder, _, names in os.walk(root):
            files += [os.path.relpath(os.path.join(folder, n), root) for n in names]
    return {f.split("/")[0] for f in files if "/" in f}


def commands(root):
    """The commands ./sdlqr's main() dispatches (its case arms)."""
    text = open(os.path.join(root, "sdlqr"), encoding="utf-8").read()
    body = text[text.index("\nmain() {"):]
    body = body[:body.index("\n}")]
    arms = re.findall(r"^    ([a-z|-]+)\)", body, re.M)
    return {name for arm in arms for name in arm.split("|")}


def executables(root):
    """Every sdlqr-NAME the build files name: the executables' output names."""
    names = set()
    for folder, _, files in os.walk(root):
        if os.path.relpath(folder, root).split(os.sep)[0] in ("build", "node_modules", ".git"):
            continue
        for file in files:
            if file == "CMakeLists.txt" or file.endswith(".cmake"):
                names |= set(EXECUTABLE.findall(open(os.path.join(folder, file), encoding="utf-8").read()))
    return names


def slug(heading):
    """GitHub's anchor of a heading."""
    text = re.sub(r"[`*_]", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    text = open(path, encoding="utf-8").read()
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    return {slug(h) for h in re.findall(r"^#+\s+(.*)$", text, re.M)}


def check_page(root, page, folders, known):
    known_commands, known_executables = known
    findings = []
    text = open(page, encoding="utf-8").read()
    prose = re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    name = os.path.relpath(page, root)
    for number, line in enumerate(text.split("\n"), 1):
        for word in SDLQR.findall(line):
            if word not in known_commands:
                findings.append(f"{name}:{number}: unknown-command ./sdlqr {word}")
        for executable in EXECUTABLE.findall(line):
            if executable not in known_executables:
                findings.append(f"{name}:{number}: unknown-executable {executable}")
    for number, line in enumerate(prose.split("\n"), 1):
        for target in LINK.findall(line):
            if re.match(r"^[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            full = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(full):
                findings.append(f"{name}:{number}: broken-link {target}")
            elif anchor and full.endswith(".md") and anchor not in anchors(full):
                findings.append(f"{name}:{number}: broken-anchor {target}")
        for code in INLINE.findall(line):
            token = code.split()[0].rstrip(":,;.)")
            if "/" not in token or NOT_LITERAL.search(token) or token.split("/")[0] not in folders:
                continue
            if not os.path.exists(os.path.join(root, token)):
                findings.append(f"{name}:{number}: missing-file {token}")
    return findings


def main():
    if len(sys.argv) != 2:
        print("usage: doc_links.py SOURCE_DIR", file=sys.stderr)
        return 2
    root = sys.argv[1]
    pages = [os.path.join(root, "README.md")]
    for folder, _, names in os.walk(os.path.join(root, "docs")):
        pages += [os.path.join(folder, n) for n in sorted(names) if n.endswith(".md")]
    folders, known = repository_entries(root), (commands(root), executables(root))
    findings = [f for page in pages if os.path.exists(page) for f in check_page(root, page, folders, known)]
    for finding in findings:
        print(finding)
    print(f"doc_links: {len(pages)} pages, {len(findings)} finding(s)")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
