#!/usr/bin/python3
"""List the functions of src/ longer than N lines (default 80), longest first.

What it counts: every function *defined* (with a body) at namespace or class scope in the .cpp
and .h files under src/: free functions, member functions defined in or out of their class,
constructors, operators, templates. Its length is the number of source lines from the first line
of its signature (the template line, if any; comments before it are not counted) to its closing
brace, inclusive; blank and comment lines inside count. Lambdas and local classes count as part of
the function that encloses them. Not counted as functions: data initialisers at namespace scope
(`const T x = {...};`, a lambda stored in such a variable included) and the braces of
namespaces, classes and enums themselves.

How: a brace-matching scan after removing comments, string and character literals (raw strings
included) and preprocessor lines. A '{' at namespace or class scope opens a function body when the
text before it since the previous declaration has a parameter list and no '=' outside brackets;
brace initialisers in a constructor's member-initialiser list (`: x_{a}`) stay part of its header.
It is a heuristic, not a C++ parser: macros that expand to braces would mislead it (src/ has none).

Usage (from the repository root):
  /usr/bin/python3 scripts/long-functions.py              # functions over 80 lines, longest first
  /usr/bin/python3 scripts/long-functions.py -n 25        # over 25 lines
  /usr/bin/python3 scripts/long-functions.py --count      # only how many
  options: --root DIR (default src), --top K (only the K longest)
"""
import argparse
import os
import re
import sys

ACCESS_LABEL = re.compile(r"\b(public|private|protected)\s*:(?!:)")
SCOPE_KEYWORD = re.compile(r"^\s*(?:template\s*<.*?>\s*)?(?:\[\[.*?\]\]\s*)*"
                           r"(?:(?:typedef|inline|export)\s+)*(namespace|class|struct|union|enum)\b", re.S)
EXTERN_BLOCK = re.compile(r'^\s*extern\s*"C(\+\+)?"\s*$')


def strip_code(text):
    """The text with comments, literals and preprocessor lines blanked out (newlines kept, so
    line numbers stay right)."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c in " \t":
            out.append(c)
            i += 1
            continue
        if at_line_start and c == "#":  # preprocessor line, with its continuations
            while i < n and not (text[i] == "\n" and text[i - 1] != "\\"):
                out.append("\n" if text[i] == "\n" else " ")
                i += 1
            continue
        at_line_start = False
        if c == "\n":
            at_line_start = True
            out.append(c)
            i += 1
        elif text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
        elif c == '"' and i > 0 and text[i - 1] == "R" and (i < 2 or not (text[i - 2].isalnum() or text[i - 2] == "_")
                                                             or text[i - 2] in "uUL8"):
            m = re.match(r'"([^(\s]*)\(', text[i:])
            delim = ")" + (m.group(1) if m else "") + '"'
            end = text.find(delim, i + 1)
            end = n if end < 0 else end + len(delim)
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
        elif c == '"' or (c == "'" and not is_digit_separator(text, i)):
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


def is_digit_separator(text, i):
    """A ' inside a number (1'000'000) is a digit separator, not a character literal."""
    j = i
    while j > 0 and (text[j - 1].isalnum() or text[j - 1] in "_.'"):
        j -= 1
    return j < i and text[j].isdigit()


def depth0_text(header):
    """The header with everything inside (), [], <> of templates and {} removed."""
    out, depth = [], 0
    for c in header:
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth = max(0, depth - 1)
        elif depth == 0:
            out.append(c)
    return "".join(out)


def has_initialiser_list(header):
    """True when the header is a constructor's signature followed by `:` (not `::`) and members."""
    depth, seen_params = 0, False
    for k, c in enumerate(header):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0 and c == ")":
                seen_params = True
        elif c == ":" and depth == 0 and seen_params:
            if header[k - 1:k] != ":" and header[k + 1:k + 2] != ":":
                return True
    return False


def without_template_prefix(header):
    """The header without its leading `template <...>` (angle brackets balanced), whose default
    arguments (`class = ...`) are no initialiser."""
    m = re.match(r"\s*template\s*<", header)
    if not m:
        return header
    depth, k = 1, m.end()
    while k < len(header) and depth:
        depth += {"<": 1, ">": -1}.get(header[k], 0)
        k += 1
    return header[k:]


def classify(header):
    """What a '{' after this header opens: 'namespace', 'class', 'function', 'brace-init' (part of
    a constructor's member-initialiser list) or 'other' (initialisers, enums, blocks)."""
    if EXTERN_BLOCK.match(header):
        return "namespace"
    m = SCOPE_KEYWORD.match(header)
    if m and "(" not in depth0_text(re.sub(r"^\s*template\s*<.*?>", "", header, flags=re.S)).split("{")[0]:
        kind = m.group(1)
        return {"namespace": "namespace", "enum": "other"}.get(kind, "class")
    flat = depth0_text(without_template_prefix(header))
    if "(" not in header or "=" in re.sub(r"operator\s*\S+", "", flat).replace("==", ""):
        return "other"
    if has_initialiser_list(header) and re.search(r"[\w>]\s*$", header):
        return "brace-init"
    return "function"


def function_name(header):
    """The name before the parameter list: the last qualified identifier (or operator) before the
    first '(' at bracket depth 0."""
    m = re.search(r"((?:[\w~]+::)*(?:operator\s*(?:\(\)|[^\s(]+)|[\w~]+))\s*\(", header)
    return m.group(1) if m else header.strip()[:40]


def scan(path):
    """The functions of one file: (first line, last line, name)."""
    with open(path, encoding="utf-8", errors="replace") as f:
        code = strip_code(f.read())
    found = []
    stack = []          # per open brace: its kind (and for a function its start line and name)
    header_start = 0    # offset where the current declaration's text began
    line = 1
    line_of = []        # line number at each offset, computed lazily below
    for k, c in enumerate(code):
        line_of.append(line)
        if c == "\n":
            line += 1
    i = 0
    while i < len(code):
        c = code[i]
        inside_function = any(kind[0] in ("function", "other") for kind in stack)
        if c == "{":
            if inside_function:
                stack.append(("block",))
            else:
                header = code[header_start:i]
                last_label = None
                for m in ACCESS_LABEL.finditer(header):
                    last_label = m
                if last_label:
                    header_start += last_label.end()
                    header = code[header_start:i]
                kind = classify(header)
                if kind == "function":
                    start = header_start + (len(header) - len(header.lstrip()))
                    stack.append(("function", line_of[start], function_name(header)))
                else:
                    stack.append((kind,))
                if kind != "brace-init":
                    header_start = i + 1
        elif c == "}":
            kind = stack.pop() if stack else ("block",)
            if kind[0] == "function":
                found.append((kind[1], line_of[i], kind[2]))
            if not any(k[0] in ("function", "other") for k in stack) and kind[0] != "brace-init":
                header_start = i + 1
        elif c == ";" and not inside_function:
            header_start = i + 1
        i += 1
    return found


def main():
    parser = argparse.ArgumentParser(description="List the functions longer than N lines, longest first.")
    parser.add_argument("-n", "--min", type=int, default=80, help="list functions longer than this many lines")
    parser.add_argument("--root", default="src", help="folder to scan (default src)")
    parser.add_argument("--top", type=int, default=0, help="only the K longest")
    parser.add_argument("--count", action="store_true", help="print only how many")
    args = parser.parse_args()
    rows = []
    for folder, _, files in os.walk(args.root):
        for name in files:
            if name.endswith((".cpp", ".h", ".hpp", ".cc")):
                path = os.path.join(folder, name)
                for first, last, fn in scan(path):
                    length = last - first + 1
                    if length > args.min:
                        rows.append((length, path, first, fn))
    rows.sort(key=lambda r: (-r[0], r[1], r[2]))
    if args.count:
        print(len(rows))
        return 0
    for length, path, first, fn in rows[: args.top or None]:
        print(f"{length:5d}  {path}:{first}  {fn}")
    print(f"{len(rows)} functions over {args.min} lines", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
