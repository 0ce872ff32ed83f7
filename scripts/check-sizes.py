#!/usr/bin/env python3
"""Checks that the engine and pipeline code stays in pieces one can hold in mind:
no source file over --max-file-lines lines, no function over --max-function-lines.

Reads C++ as clang-format writes it in this project. It blanks comments and
string literals, then follows the braces: a brace whose declaration has a
parameter list and which opens outside any function is a function body (a
lambda counts as part of the function that holds it). A function's length runs
from the first line of its declaration to its closing brace, as ctags counts.

Usage: check-sizes.py [--max-file-lines N] [--max-function-lines N] DIR_OR_FILE...
Prints each offender and exits 1 when there is one.
"""
import argparse
import os
import re
import sys

SOURCE_SUFFIXES = (".h", ".cpp", ".cxx", ".hpp", ".txx")
SCOPE_KEYWORDS = re.compile(r"\b(namespace|class|struct|union|enum)\b")
CONTROL_KEYWORDS = re.compile(r"^\s*(if|for|while|switch|catch|do|else)\b")


def blank_comments_and_strings(text):
    """The text with comments, string and character literals replaced by spaces
    (newlines kept, so line numbers stay right)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(text):
    """(name, first line, length in lines) of each function body in the text."""
    code = blank_comments_and_strings(text)
    # Preprocessor lines never open a scope; blank them too.
    code = re.sub(r"(?m)^[ \t]*#.*(\\\n.*)*$", lambda m: re.sub(r"[^\n]", " ", m.group(0)), code)
    found = []
    stack = []  # one entry per open brace: "scope", "function", "block"
    declaration_start = 0  # where the text before the next brace begins
    function_start = None
    for i, c in enumerate(code):
        if c in ";":
            if "function" not in stack:
                declaration_start = i + 1
        elif c == "{":
            inside_function = "function" in stack
            declaration = code[declaration_start:i]
            kind = "block"
            if not inside_function:
                if SCOPE_KEYWORDS.search(declaration) and "(" not in declaration.split("=")[0]:
                    kind = "scope"
                elif "(" in declaration and "=" not in declaration.split("(")[0] \
                        and not CONTROL_KEYWORDS.match(declaration):
                    kind = "function"
                    stripped = declaration.lstrip()
                    start = i - len(declaration) + (len(declaration) - len(stripped))
                    name = re.findall(r"([~\w:]+)\s*\(", declaration)
                    function_start = (name[0] if name else "?", start)
            stack.append(kind)
            if not inside_function:
                declaration_start = i + 1
        elif c == "}":
            kind = stack.pop() if stack else "block"
            if kind == "function" and "function" not in stack and function_start:
                name, start = function_start
                first = code.count("\n", 0, start) + 1
                last = code.count("\n", 0, i) + 1
                found.append((name, first, last - first + 1))
                function_start = None
            if "function" not in stack:
                declaration_start = i + 1
    return found


def sources(paths):
    for path in paths:
        if os.path.isdir(path):
            for root, _, names in os.walk(path):
                for name in sorted(names):
                    if name.endswith(SOURCE_SUFFIXES):
                        yield os.path.join(root, name)
        else:
            yield path


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--max-file-lines", type=int, default=700)
    parser.add_argument("--max-function-lines", type=int, default=100)
    parser.add_argument("--list", type=int, metavar="N",
                        help="also list every function over N lines (no failure)")
    parser.add_argument("paths", nargs="+")
    args = parser.parse_args()
    offenders = 0
    checked = 0
    for path in sources(args.paths):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        checked += 1
        lines = text.count("\n")
        if lines > args.max_file_lines:
            print("%s: %d lines (at most %d)" % (path, lines, args.max_file_lines))
            offenders += 1
        for name, first, length in functions(text):
            if length > args.max_function_lines:
                print("%s:%d: %s is %d lines (at most %d)"
                      % (path, first, name, length, args.max_function_lines))
                offenders += 1
            elif args.list is not None and length > args.list:
                print("%s:%d: %s is %d lines" % (path, first, name, length))
    if checked == 0:
        print("no source files found under %s" % " ".join(args.paths))
        return 1
    print("%d files checked, %d over the limits" % (checked, offenders))
    return 1 if offenders else 0


if __name__ == "__main__":
    sys.exit(main())
