#!/usr/bin/python3
"""No function longer than 80 lines in the repository's C++ (generated code and the solver
kernels aside). A brace-matching scan: comments and literals are blanked, a '{' whose statement
head ends in ')' (optionally followed by const/noexcept/override/-> type/initializer list) opens a
function body at namespace or class level; its length is the lines from its head to its '}'.
  function_length.py ROOT [MAX_LINES]   exit 0 clean, 1 with one line per function too long."""
import os
import re
import sys

SKIP_DIRS = {"build", ".git", "node_modules", "third_party"}
# Solver kernels: fixed-size arithmetic unrolled on purpose (issue 22, item 7).
KERNELS = ("common/math/src/sda_kernel.hpp", "common/math/src/discretize.cpp", "common/math/src/riccati.cpp",
           "common/math/src/small_kernels.hpp", "common/math/src/vector_kernels.hpp",
           "common/math/src/certificate_kernel.hpp")
# Functions still over the limit, each to be split (issue 22, item 7). The list only shrinks: a
# listed function that is no longer too long (or gone) fails too, so it cannot go stale.
PENDING = set()
CONTAINERS = re.compile(r"\b(namespace|class|struct|union|enum|extern)\b")


def digit_separator(text, i):
    """The quote at i sits inside a number (1'800'000, 0xFF'FF): the run of letters, digits, dots
    and quotes before it starts with a digit. A character literal's prefix (u8'a', L'a') starts
    with a letter; taken for a literal, a separator would blank the rest of its line, braces too."""
    j = i
    while j > 0 and (text[j - 1].isalnum() or text[j - 1] in "_.'"):
        j -= 1
    return j < i and text[j].isdigit()


def blank(text):
    """Comments, string and char literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif c == "'" and digit_separator(text, i):
            out.append(c); i += 1
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else "")); i = j + 1
        else:
            out.append(c); i += 1
    return "".join(out)


def is_function_head(head):
    head = re.sub(r"\s+", " ", head).strip()
    if not head or CONTAINERS.search(head.split("(")[0]) or head.startswith("#"):
        return False
    if re.search(r"(^|[^=!<>])=\s*[^=]*$", head.split(")")[-1]):  # x = {...}
        return False
    if re.match(r"^(if|for|while|switch|do|else|try|catch)\b", head) or head.endswith(("else", "do", "try")):
        return False
    return ")" in head and "(" in head


def scan(path, text, limit):
    clean = blank(text)
    found = []
    depth_kind = []  # 'c' container, 'f' function, 'o' other
    head_start = 0
    line = 1
    opened = []  # (kind, start line, name)
    i = 0
    for i, c in enumerate(clean):
        if c == "\n":
            line += 1
        elif c in ";}":
            if c == "}" and opened:
                kind, start, name = opened.pop()
                if kind == "f" and line - start + 1 > limit:
                    found.append((start, line - start + 1, name))
            head_start = i + 1
        elif c == "{":
            head = clean[head_start:i]
            inside_function = any(k in "fo" for k, _, _ in opened)
            if inside_function:
                kind = "o"
            elif is_function_head(head):
                kind = "f"
            elif CONTAINERS.search(head):
                kind = "c"
            else:
                kind = "o"
            start = line - head.rstrip().count("\n") if kind == "f" else line
            first = head.lstrip()
            start = line - clean[head_start + len(head) - len(first):i].count("\n")
            name = re.sub(r"\s+", " ", first.split("(")[0]).strip().split(" ")[-1] if kind == "f" else ""
            opened.append((kind, start, name))
            head_start = i + 1
    return found


def main():
    root = sys.argv[1]
    limit = int(sys.argv[2]) if len(sys.argv) > 2 else 80
    root_is_repository = os.path.exists(os.path.join(root, "sdlqr")) and os.path.isdir(os.path.join(root, "lcmtypes"))
    bad = 0
    pending_seen = set()
    for base, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("build"))
        for f in sorted(files):
            if not f.endswith((".cpp", ".hpp", ".cc", ".h")):
                continue
            path = os.path.join(base, f)
            rel = os.path.relpath(path, root)
            if rel.startswith(KERNELS) or "/generated/" in rel:
                continue
            with open(path, encoding="utf-8", errors="replace") as fh:
                text = fh.read()
            for start, length, name in scan(rel, text, limit):
                if root_is_repository and (rel, name) in PENDING:
                    pending_seen.add((rel, name))
                    continue
                print(f"{rel}:{start}: function-too-long {name} is {length} lines (max {limit})")
                bad += 1
    if root_is_repository:
        for rel, name in sorted(PENDING - pending_seen):
            print(f"{rel}: function-length-list-stale {name} is no longer over {limit} lines: remove it from PENDING")
            bad += 1
    if bad:
        return 1
    print(f"no function over {limit} lines but the {len(pending_seen)} listed as still to split")
    return 0


if __name__ == "__main__":
    sys.exit(main())
