"""Comments say what and why; the history of a change (which issue asked for it) belongs in its commit message.
No comment or docstring of the code, the tests or the build names an issue of the tracker by its number: the
tracker is not in the repository, so the reference means nothing to whoever carries on."""
import ast
import io
import os
import re
import tokenize

SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
ISSUE = re.compile(r"\bissues? \d+", re.IGNORECASE)


def python_comments(text):
    """(line, text) of each comment and docstring of a Python source."""
    found = [(t.start[0], t.string) for t in tokenize.generate_tokens(io.StringIO(text).readline)
             if t.type == tokenize.COMMENT]
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            doc = ast.get_docstring(node, clean=False)
            if doc:
                found.append((node.body[0].lineno, doc))
    return found


def line_comments(text, marker):
    """(line, text) of what follows `marker` ("//" or "#") on each line, string literals aside (roughly: a
    marker inside quotes on a line with an even count of quotes before it is a comment's)."""
    found = []
    for number, line in enumerate(text.splitlines(), 1):
        at = line.find(marker)
        while at >= 0 and line[:at].count('"') % 2:
            at = line.find(marker, at + 1)
        if at >= 0:
            found.append((number, line[at:]))
    return found


def comments(path, text):
    if path.endswith(".py"):
        return python_comments(text)
    if path.endswith((".cpp", ".h", ".js")):
        return line_comments(text, "//")
    return line_comments(text, "#")


def sources():
    """The code, tests, build files and tools, as paths from the source root (no git: CI's Debian 13 copy has no
    .git)."""
    found = [name for name in ("Makefile", "CMakeLists.txt", ".ci/run") if os.path.exists(os.path.join(SOURCE, name))]
    for top in ("App", "python", "freecad", "tests", "tools"):
        for folder, _, files in os.walk(os.path.join(SOURCE, top)):
            for name in files:
                path = os.path.relpath(os.path.join(folder, name), SOURCE)
                if re.search(r"\.(cpp|h|py|js|cmake)$|CMakeLists\.txt$|^tools/[^./]*$", path):
                    found.append(path)
    return sorted(found)


def test_no_comment_names_an_issue():
    found = []
    for path in sources():
        with open(os.path.join(SOURCE, path), encoding="utf-8") as f:
            text = f.read()
        found += ["{}:{}: {}".format(path, line, ISSUE.search(c).group(0))
                  for line, c in comments(path, text) if ISSUE.search(c)]
    assert not found, "\n".join(found)


def test_the_check_finds_an_issue_in_each_kind_of_comment():
    assert [c for _, c in python_comments('"""Made for issue 3."""\nx = 1  # issue 4\ny = "issue 5"\n')
            if ISSUE.search(c)] == ["# issue 4", "Made for issue 3."]
    assert [c for _, c in line_comments('a = "//";  // issue 6\nb = "issue 7";\n', "//")] == ["// issue 6"]
