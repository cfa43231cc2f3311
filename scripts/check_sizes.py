#!/usr/bin/env python3
"""Fails when a source file is over 500 lines or a function outside the tests
is over 120 (docs/architecture.md, "Sizes"): code that grows past them is
split into named steps before it grows further.

    scripts/check_sizes.py [--max-file 500] [--max-function 120] [ROOT]

Files: src/, python/, benchmarks/ and fuzz/ (.h, .cc).  Function bodies are
found by matching braces after comments and literals are blanked: a brace
block that follows a parenthesis outside any other function is a function
(lambdas count toward the function they stand in), from its signature's first
line to its closing brace.  Test files (*_test.cc) count toward the file
limit only: a test reads best as one scenario.
"""
import argparse
import pathlib
import re
import sys

FOLDERS = ("src", "python", "benchmarks", "fuzz")


def blank_comments_and_literals(text):
    """The text with comments and string/char literals as spaces, newlines kept."""
    out = []
    i, n = 0, len(text)

    def blank(j):
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        return j

    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = blank(n if j < 0 else j)
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = blank(n if j < 0 else j + 2)
        elif text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            delimiter = re.match(r'R"([^(\s]*)\(', text[i:])
            if delimiter is None:
                out.append(text[i])
                i += 1
                continue
            end = ")" + delimiter.group(1) + '"'
            j = text.find(end, i)
            i = blank(n if j < 0 else j + len(end))
        elif text[i] in "\"'":
            # A digit separator (1'000) is no literal.
            if text[i] == "'" and i > 0 and text[i - 1].isalnum():
                out.append(text[i])
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != text[i] and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = blank(min(j + 1, n))
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def block_kind(head, inside_function):
    """What a '{' opens, from the text since the last ';', '{' or '}'."""
    if inside_function:
        return "other"
    if re.search(r"\bnamespace\b|\bextern\b", head):
        return "namespace"
    if re.search(r"\b(class|struct|union|enum)\b", head) and "(" not in head:
        return "class"
    if ")" in head and not head.rstrip().endswith("="):
        return "function"
    return "other"


def functions(text):
    """(first line, length in lines, signature) of each function body."""
    code = blank_comments_and_literals(text)
    stack = []  # (kind, first line, signature)
    head_start = 0
    found = []
    for i, c in enumerate(code):
        if c == "{":
            head = code[head_start:i]
            inside = any(kind == "function" for kind, _, _ in stack)
            start = head_start + len(head) - len(head.lstrip())
            line = code.count("\n", 0, start) + 1
            signature = " ".join(head.split())[:70]
            stack.append((block_kind(head, inside), line, signature))
            head_start = i + 1
        elif c == "}":
            if stack:
                kind, line, signature = stack.pop()
                if kind == "function":
                    end = code.count("\n", 0, i) + 1
                    found.append((line, end - line + 1, signature))
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-file", type=int, default=500)
    parser.add_argument("--max-function", type=int, default=120)
    parser.add_argument("root", nargs="?", default=pathlib.Path(__file__).parent.parent)
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    problems = []
    checked = 0
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".h", ".cc"):
                continue
            checked += 1
            text = path.read_text(encoding="utf-8", errors="replace")
            name = path.relative_to(root)
            lines = text.count("\n")
            if lines > args.max_file:
                problems.append(f"{name}: {lines} lines (at most {args.max_file})")
            if path.name.endswith("_test.cc"):
                continue
            for line, length, signature in functions(text):
                if length > args.max_function:
                    problems.append(
                        f"{name}:{line}: a function of {length} lines (at most "
                        f"{args.max_function}): {signature}")
    for problem in problems:
        print(problem)
    if problems:
        return 1
    print(f"sizes: {checked} files, none over {args.max_file} lines, no function "
          f"over {args.max_function}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
