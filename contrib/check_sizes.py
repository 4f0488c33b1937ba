#!/usr/bin/env python3
"""Lines per file and per function in the library (or any C++ tree).

Usage: contrib/check_sizes.py [--file-limit N] [--function-limit N] [--top K] PATH...

A function is a brace block opened at namespace level (outside any other
block): a free function, a member function defined out of class, or a
function defined inside a class body in a header. Class and struct bodies
are looked into, not counted. Lambdas count towards the function that holds
them. Exits 1 when a file or a function is over its limit.
"""
import argparse
import os
import re
import sys


def strip(text):
    """Blanks out comments, strings and character literals, keeping lines."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            if m:
                end = ")" + m.group(1) + '"'
                j = text.find(end, i + len(m.group(0)))
                j = n if j < 0 else j + len(end)
                out.append('""' + "\n" * text.count("\n", i, j))
                i = j
            else:
                out.append(c)
                i += 1
        elif c in "\"'":
            if c == "'" and i > 0 and (text[i - 1].isalnum()):
                out.append(c)  # digit separator
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    text = strip(open(path, encoding="utf-8", errors="replace").read())
    lines = text.split("\n")
    result = []
    # stack of (kind, start line, name)
    stack = []
    statement = ""
    for lineno, line in enumerate(lines, 1):
        for ch in line:
            if ch == "{":
                head = statement.strip()
                inside_function = any(k == "function" for k, _, _ in stack)
                if inside_function:
                    kind = "block"
                elif re.search(r"\bnamespace\b[^;()]*$", head) or head.startswith("extern"):
                    kind = "namespace"
                elif re.search(r"\b(class|struct|union|enum)\b[^()]*$", head) and not head.endswith(")"):
                    kind = "class"
                elif "(" in head:
                    kind = "function"
                else:
                    kind = "block"  # initialisers at namespace scope
                name = ""
                if kind == "function":
                    m = re.search(r"([~\w:<>]+)\s*\((?:[^()]|\([^()]*\))*\)[^(]*$", head)
                    name = m.group(1) if m else head[-60:]
                stack.append((kind, lineno, name))
                statement = ""
            elif ch == "}":
                if stack:
                    kind, start, name = stack.pop()
                    if kind == "function":
                        result.append((lineno - start + 1, name, start))
                statement = ""
            elif ch == ";":
                statement = ""
            else:
                statement += ch
        statement += " "
    return len(lines) - (1 if text.endswith("\n") else 0), result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("paths", nargs="+")
    parser.add_argument("--file-limit", type=int, default=800)
    parser.add_argument("--function-limit", type=int, default=100)
    parser.add_argument("--top", type=int, default=3)
    args = parser.parse_args()
    files = []
    for p in args.paths:
        if os.path.isdir(p):
            for root, _, names in os.walk(p):
                files += [os.path.join(root, f) for f in names if f.endswith((".cc", ".h"))]
        else:
            files.append(p)
    file_sizes, function_sizes = [], []
    for f in sorted(files):
        n, funcs = functions(f)
        file_sizes.append((n, f))
        function_sizes += [(length, f"{f}:{start} {name}") for length, name, start in funcs]
    file_sizes.sort(reverse=True)
    function_sizes.sort(reverse=True)
    long_files = [x for x in file_sizes if x[0] > args.file_limit]
    long_functions = [x for x in function_sizes if x[0] > args.function_limit]
    print(f"largest files (limit {args.file_limit} lines):")
    for n, f in file_sizes[: max(args.top, len(long_files))]:
        print(f"  {n:6d}  {f}")
    print(f"largest functions (limit {args.function_limit} lines):")
    for n, f in function_sizes[: max(args.top, len(long_functions))]:
        print(f"  {n:6d}  {f}")
    print(f"{len(long_files)} files and {len(long_functions)} functions over the limits")
    return 1 if long_files or long_functions else 0


if __name__ == "__main__":
    sys.exit(main())
