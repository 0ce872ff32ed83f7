#!/usr/bin/env python3
"""Fails on a backticked repository path in README.md or docs/*.md that names
no file of the source tree (ctest docs.Paths).

A backticked token is taken as a repository path when its first component is
a top-level folder of the repository (`Core/Field/VectorField.h`,
`bench/run.sh`; without an extension, `Core/Field/VectorField`, a folder or
the stem of a file), and as a file name when it has no folder but a source
file's extension (`TracerOutput.cxx`, `bp_slip.glsl`): the first must exist,
the second must be the name of some file in the tree. A file the build
writes counts where the project's CMake code names it
(`vtkBoundParticleTracerEnumerations.cxx`). Braces expand
(`Core/Field/VectorField.{h,cpp}`), a trailing `:LINE` or `#anchor` is
dropped, and a token with a wildcard, an ellipsis, a variable or angle
brackets (`<catalyst.h>`, another project's header) is not a path.

A Markdown link to a heading of these documents (`[x](performance.md#meshes)`,
`[x](#output)`) must find that heading (GitHub's anchors).

EXEMPT lists paths the docs may name that are not in the source tree (a
file the build generates, say), each with its reason. It should stay empty:
an exemption that no document uses any more is itself an error.

Usage: check-doc-paths.py [ROOT]   (ROOT: the repository, default: this
script's parent folder's parent)
"""
import os
import re
import sys

EXEMPT = {
    # path: why the docs may name it although it is no file of the tree
}

SOURCE_EXTENSIONS = (".h", ".hpp", ".cpp", ".cxx", ".c", ".glsl", ".py", ".sh", ".in")


def expand(token):
    """`a.{h,cpp}` -> [`a.h`, `a.cpp`]; nested or several braces expand in turn."""
    m = re.search(r"\{([^{}]*)\}", token)
    if not m:
        return [token]
    out = []
    for part in m.group(1).split(","):
        out.extend(expand(token[:m.start()] + part + token[m.end():]))
    return out


def anchors(markdown):
    """The anchors GitHub gives the headings of a Markdown text."""
    out, fenced = set(), False
    for line in markdown.split("\n"):
        if line.startswith("```"):
            fenced = not fenced
        m = None if fenced else re.match(r"#{1,6} +(.*?) *#* *$", line)
        if m:
            slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
            anchor, n = slug, 1
            while anchor in out:
                anchor, n = "%s-%d" % (slug, n), n + 1
            out.add(anchor)
    return out


def candidates(text):
    for token in re.findall(r"`([^`\n]+)`", text):
        token = token.strip()
        if " " in token or not token:
            continue
        if any(c in token for c in "*?$<>…|=") or "..." in token:
            continue
        token = re.sub(r"(:\d+(-\d+)?|#[\w-]+)$", "", token).rstrip("/")
        yield token


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), ".."))
    top = {name for name in os.listdir(root)
           if os.path.isdir(os.path.join(root, name)) and not name.startswith(".")
           and name not in ("build", "shared")}
    basenames, cmake_text = set(), []
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if not d.startswith(".") and
                   not (folder == root and d in ("build", "shared")) and
                   not d.startswith("build-")]
        basenames.update(files)
        for name in files:
            if name == "CMakeLists.txt" or name.endswith(".cmake"):
                with open(os.path.join(folder, name), encoding="utf-8") as f:
                    cmake_text.append(f.read())
    cmake_text = "\n".join(cmake_text)

    def exists(path):
        if os.path.exists(os.path.join(root, path)):
            return True
        name = os.path.basename(path)
        if "." not in name:  # a unit named by its stem: Core/Field/VectorField
            folder = os.path.join(root, os.path.dirname(path))
            return os.path.isdir(folder) and any(
                f.split(".", 1)[0] == name for f in os.listdir(folder))
        return re.search(r"(^|[/\s\"])" + re.escape(name) + r"($|[\s\")])", cmake_text) is not None
    docs = ["README.md"] + sorted(os.path.join("docs", f)
                                  for f in os.listdir(os.path.join(root, "docs"))
                                  if f.endswith(".md"))
    stale, used, texts = [], set(), {}
    for doc in docs:
        with open(os.path.join(root, doc), encoding="utf-8") as f:
            texts[doc] = f.read()
    for doc in docs:
        lines = texts[doc].split("\n")
        for number, line in enumerate(lines, 1):
            for target, anchor in re.findall(r"\]\(([\w./-]*\.md|)#([^)\s]+)\)", line):
                target = os.path.normpath(os.path.join(os.path.dirname(doc), target)) \
                    if target else doc
                if target in texts and anchor not in anchors(texts[target]):
                    stale.append("%s:%d: no heading of %s has the anchor #%s" %
                                 (doc, number, target, anchor))
            for token in candidates(line):
                for path in expand(token):
                    first = path.split("/", 1)[0]
                    if "/" in path and first in top:
                        found = exists(path)
                    elif "/" not in path and path.endswith(SOURCE_EXTENSIONS) and \
                            not path.startswith("."):
                        found = path in basenames or exists(path)
                    else:
                        continue
                    if path in EXEMPT:
                        used.add(path)
                        continue
                    if not found:
                        stale.append("%s:%d: `%s` names no file of the tree" % (doc, number, path))
    for path in sorted(set(EXEMPT) - used):
        stale.append("scripts/check-doc-paths.py: EXEMPT names `%s`, which no document uses" % path)
    for message in stale:
        print(message)
    print("%d stale path(s) in %d documents" % (len(stale), len(docs)))
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
