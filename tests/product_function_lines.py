#!/usr/bin/env python3
"""product_function_lines.py SOURCE_DIR LIMIT: fails, naming them, when any function of the
product's C++ (core/ and app/) is over LIMIT lines, counted as Universal Ctags counts them: from
the line of its parameter list to that of its closing brace. A function that long does more than
one step; split it into functions that read as its steps rather than raise the limit.
product_function_lines.py --self-test: checks the scanner on generated code.

The scanner matches braces in the code with comments, string and character literals and
preprocessor lines blanked out. A brace at namespace or class scope opens a function body when the
text before it holds a parameter list and is neither a class, struct, union or enum head nor an
initializer (a top-level `=`); everything inside a body, lambdas included, is the function's.
"""
import pathlib
import re
import sys

from product_checks import report, self_test_result, usage


def blank_non_code(text):
    """The text with comments, literals and preprocessor lines replaced by spaces, newlines kept."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#" or (line_start and c in " \t" and text[i:].lstrip(" \t").startswith("#")):
            # A preprocessor line, with its continuations.
            j = i
            while j < n and not (text[j] == "\n" and text[j - 1] != "\\"):
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif (m := re.match(r'R"([^()\\ ]{0,16})\(', text[i:])) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
        elif c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000 is a digit separator
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
        else:
            out.append(c)
            line_start = c == "\n"
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        i = j
    return "".join(out)


def top_level(header, chars):
    """Whether any of chars occurs in header outside parentheses, brackets and angle brackets."""
    depth = 0
    for c in header:
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif depth == 0 and c in chars:
            return True
    return False


def is_function_head(header):
    head = re.sub(r"^\s*template\s*<.*?>\s*(?=[A-Za-z_])", "", header, flags=re.S)
    head = re.sub(r"__attribute__\s*\(\(.*?\)\)|\[\[.*?\]\]|alignas\s*\(.*?\)", " ", head, flags=re.S)
    if "(" not in head:
        return False
    if re.match(r"\s*(?:\w+\s+)*?(class|struct|union|enum|namespace)\b", head.split("(")[0]):
        return False
    operator = re.search(r"\boperator\b", head)
    return operator is not None or not top_level(head, "=")


def long_functions(text, limit):
    """(name, first line, lines) of each function of the C++ text over limit lines."""
    code = blank_non_code(text)
    found = []
    # Each open brace: whether it is a function body ("body"), inside one or an initializer
    # ("inner"), or a scope that may hold functions ("scope").
    stack = []
    header_start = 0
    for i, c in enumerate(code):
        if c == "{":
            if stack and stack[-1][0] != "scope":
                stack.append(("inner", i))
            else:
                header = code[header_start:i]
                if is_function_head(header):
                    paren = header_start + header.index("(")
                    name = re.findall(r"[~\w:]+(?=\s*$)", code[header_start:paren])
                    stack.append(("body", paren, name[0] if name else "?"))
                else:
                    stack.append(("scope" if not top_level(header, "=") else "inner", i))
            header_start = i + 1
        elif c == "}":
            if stack:
                top = stack.pop()
                if top[0] == "body":
                    first = code.count("\n", 0, top[1]) + 1
                    lines = code.count("\n", 0, i) + 1 - first + 1
                    if lines > limit:
                        found.append((top[2], first, lines))
            header_start = i + 1
        elif c == ";" or (c == ":" and re.search(r"\b(public|private|protected)\s*$", code[header_start:i])):
            if not stack or stack[-1][0] == "scope":
                header_start = i + 1
    return found


def function_text(name, lines):
    """A function of exactly `lines` lines, with what might mislead a scanner inside."""
    body = [f"int {name}(int a,", "        int b) {", '    const char* s = "}{";  // }', "    char c = '}';",
            "    auto f = [&](int x) { return x + 1; };", "    /* { */"]
    body += ["    a += f(b);"] * (lines - len(body) - 2)
    body += ["    return a + (c == '{') + int(s[0]);", "}"]
    return "\n".join(body) + "\n"


def self_test():
    """The scanner on generated code: a 101-line function fails, 100 lines pass, and what is no
    function (a struct, an initializer, a namespace) is not counted."""
    prefix = ("#include <vector>\n#define BRACE {\nnamespace woven {\nnamespace {\nconstexpr int kTable[] = {\n" +
              "    1,\n" * 120 + "};\nstruct Holder {\n    int member() const { return 1; }\n};\n}  // namespace\n")
    suffix = "}  // namespace woven\n"
    checks = [
        (long_functions(prefix + function_text("fits", 100) + suffix, 100), []),
        (long_functions(prefix + function_text("tooLong", 101) + suffix, 100), [("tooLong", 131, 101)]),
        (long_functions("class A {\npublic:\n    void f() {\n" + "    int x;\n" * 100 + "    }\n};\n", 100), [("f", 3, 102)]),
        (long_functions("A::A(int x)\n    : x_(x) {\n" + "    x_ += 1;\n" * 99 + "}\n", 100), [("A::A", 1, 102)]),
    ]
    return self_test_result("scanner", checks)


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 3:
        return usage(__doc__)
    root, limit = pathlib.Path(argv[1]), int(argv[2])
    over = []
    for folder in ("core", "app"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix in (".cpp", ".h") and path.is_file():
                for name, line, lines in long_functions(path.read_text(encoding="utf-8", errors="replace"), limit):
                    over.append(f"  {path.relative_to(root)}:{line}: {name}, {lines} lines")
    return report(over, f"product functions over {limit} lines (split each into its steps):",
                  f"no product function over {limit} lines")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
