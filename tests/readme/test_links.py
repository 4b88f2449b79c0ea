#!/usr/bin/env python3
"""test_links.py SRCDIR -- every relative Markdown link of README.md and papers/ resolves.

Reads README.md, papers/*.md and papers/log/*.md; for each link `[text](target)` whose
target is not a URL or an anchor, the file it names (relative to the linking file, the
`#anchor` dropped) must exist; relcol.md's `figures/...` are made by `ninja paper` and
not committed, so they are not asked for. Also every mention `papers/<name>.md` in the source tree's
C, Python, shell, meson and Markdown files must name a file of papers/. Prints each
broken link with its file and line; exit 1 if there is one (or nothing was read)."""
import os
import re
import sys

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
MENTION = re.compile(r"papers/([A-Za-z0-9_./-]+?\.md)")
EXTS = (".c", ".h", ".py", ".sh", ".md", ".build", ".js", ".mjs")


def md_files(src):
    out = [os.path.join(src, "README.md")]
    for d in ("papers", os.path.join("papers", "log")):
        full = os.path.join(src, d)
        out += sorted(os.path.join(full, f) for f in os.listdir(full) if f.endswith(".md"))
    return out


def main():
    src = os.path.abspath(sys.argv[1])
    bad = links = mentions = 0
    for path in md_files(src):
        for n, line in enumerate(open(path, encoding="utf-8"), 1):
            for target in LINK.findall(line):
                if re.match(r"[a-z]+:", target) or target.startswith("#"):
                    continue
                if target.startswith("figures/") and os.path.basename(path) == "relcol.md":
                    continue
                links += 1
                t = os.path.normpath(os.path.join(os.path.dirname(path), target.split("#")[0]))
                if not os.path.exists(t):
                    bad += 1
                    print(f"{os.path.relpath(path, src)}:{n}: link to {target}: no such file")
    for top in ("lib", "apps", "tests", "python", "scripts", "notebooks-c", "web", "data",
                "papers"):
        for root, dirs, files in os.walk(os.path.join(src, top)):
            dirs[:] = [d for d in dirs if d not in ("node_modules", "cjson")]
            for f in files:
                if not f.endswith(EXTS):
                    continue
                path = os.path.join(root, f)
                try:
                    text = open(path, encoding="utf-8").read()
                except UnicodeDecodeError:
                    continue
                for m in MENTION.finditer(text):
                    mentions += 1
                    if not os.path.exists(os.path.join(src, "papers", m.group(1))):
                        bad += 1
                        line = text.count("\n", 0, m.start()) + 1
                        print(f"{os.path.relpath(path, src)}:{line}: papers/{m.group(1)}: "
                              "no such file")
    print(f"{links} links and {mentions} mentions of papers/ read, {bad} broken")
    return 1 if bad or links == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
