#!/usr/bin/env python3
"""test_readme.py README BINDIR [SRCDIR] -- every `$` example in the README, run and compared.

A code block's (fenced, or indented by four spaces) lines starting with "$ " are commands (continued over the next lines while
a quote is open or a line ends with a backslash); the lines after a command, up to the
next command or the end of the block, are its expected output (stdout and stderr
together, as a terminal shows them). The commands run in one scratch folder, in order, with
BINDIR's apps first on PATH and the source tree's data/ and scripts/ beside them, so that
later examples read the files earlier ones wrote.

Comparison, line by line: the text between numbers must match exactly (runs of spaces
count as one); numbers must agree to a relative 1e-9 (every app prints deterministic
results: the same bits on every build of the CI, the printed digits beyond 1e-9 are kept
only so that a reader can see them), and two numbers both below 1e-12 in magnitude are
round-off alike. A line "..." in the README stands for any number of lines, and "…"
inside a line for any text.

With --update, an example whose output differs and has no "..." or "…" gets the app's
output written into the README in place of its own (for a maintainer who changed an app
on purpose: the diff then shows what changed).

Commands that cannot run here are named in SKIP with the reason (benchmarks against
other code, a checkout of another repository); every other `$` line is run.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

SKIP = {
    "scripts/bench-vs-edmd.sh": "a benchmark against a checkout of EDMD (minutes, and a fetch)",
    "scripts/ab-revs.sh": "a benchmark of two revisions (builds both; minutes)",
    "mpirun": "needs an MPI launcher; the sweep's MPI identity is tests/sweep/test_sweep.sh",
    "meson": "the build itself",
    "bash scripts/": "the README's set-up commands (they are what CI runs)",
    "sudo": "the README's set-up commands",
    "python3 -m http.server": "a server",
    "scripts/web.sh": "a server (tests/web runs the page)",
}
REL, FLOOR = 1e-9, 1e-12
NUM = re.compile(r"[-+]?(?:\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?|inf|nan)")


def complete(cmd):
    if cmd.endswith("\\"):
        return False
    try:
        shlex.split(cmd)
        return True
    except ValueError:
        return False


def fence_indented(lines):
    """Indented code blocks (4 spaces) turned into fenced ones, line numbers kept: a run of
    indented lines outside a fence whose first line is a command."""
    out, i, fence = [], 0, False
    while i < len(lines):
        ln = lines[i]
        if ln.startswith("```"):
            fence = not fence
        if not fence and ln.startswith("    $ "):
            j = i
            while j < len(lines) and lines[j].startswith("    "):
                j += 1
            # (the fences replace the lines around the block, which are blank or text)
            out[-1:] = ["```"] if out else ["```"]
            out.extend(x[4:] for x in lines[i:j])
            out.append("```")
            i = j + 1
            continue
        out.append(ln)
        i += 1
    return out


def examples(text):
    """(line number, command, [expected lines]) for every $ line in a code block."""
    out, lines, i, fence = [], fence_indented(text.split("\n")), 0, False
    while i < len(lines):
        ln = lines[i]
        if ln.startswith("```"):
            fence = not fence
            i += 1
            continue
        if fence and ln.startswith("$ "):
            start, cmd = i + 1, ln[2:]
            while not complete(cmd) and i + 1 < len(lines) and not lines[i + 1].startswith("```"):
                i += 1
                cmd += "\n" + lines[i]
            exp = []
            i += 1
            first = i
            while i < len(lines) and not lines[i].startswith("$ ") and not lines[i].startswith("```"):
                exp.append(lines[i])
                i += 1
            out.append((start, cmd, exp, first))
            continue
        i += 1
    return out


def split(line):
    """The line as alternating text and numbers (numbers as floats)."""
    parts, pos = [], 0
    for m in NUM.finditer(line):
        parts.append(" ".join(line[pos:m.start()].split()))
        parts.append(float(m.group()))
        pos = m.end()
    parts.append(" ".join(line[pos:].split()))
    return parts


def same_num(a, b):
    if a == b or (a != a and b != b):
        return True
    if abs(a) < FLOOR and abs(b) < FLOOR:
        return True
    return abs(a - b) <= REL * max(abs(a), abs(b))


def line_matches(exp, got):
    if "…" in exp:
        pat = ".*".join(re.escape(" ".join(p.split())) for p in exp.split("…"))
        return re.fullmatch(pat, " ".join(got.split())) is not None
    e, g = split(exp), split(got)
    if len(e) != len(g):
        return False
    for x, y in zip(e, g):
        if isinstance(x, float):
            if not same_num(x, y):
                return False
        elif x != y:
            return False
    return True


def matches_any_layout(exp, got):
    """The same words and numbers whatever the line breaks: ls prints columns on a terminal
    and one name a line into a pipe."""
    if any(e.strip() == "..." or "…" in e for e in exp):
        return False
    return line_matches(" ".join(exp), " ".join(got))


def matches(exp, got):
    """exp with "..." lines against got (lists of lines)."""
    if not exp:
        return not got
    if exp[0].strip() == "...":
        return any(matches(exp[1:], got[k:]) for k in range(len(got) + 1))
    return bool(got) and line_matches(exp[0], got[0]) and matches(exp[1:], got[1:])


def main():
    update = "--update" in sys.argv
    args = [a for a in sys.argv[1:] if a != "--update"]
    readme, bindir = args[0], os.path.abspath(args[1])
    src = os.path.abspath(args[2] if len(args) > 2 else os.path.dirname(readme))
    text = open(readme, encoding="utf-8").read().split("\n")
    exs = examples("\n".join(text))
    edits = []
    apps = sorted({os.path.join(bindir, "apps", d) for d in os.listdir(os.path.join(bindir, "apps"))
                   if os.path.isdir(os.path.join(bindir, "apps", d))})
    env = dict(os.environ, PATH=os.pathsep.join(apps + [os.environ.get("PATH", "")]),
               LC_ALL="C", OMP_NUM_THREADS="1")
    env.pop("CI", None)
    work = tempfile.mkdtemp(prefix="relcol-readme-")
    for d in ("data", "scripts"):
        os.symlink(os.path.join(src, d), os.path.join(work, d))
    fails = ran = skipped = 0
    try:
        for line, cmd, exp, first in exs:
            why = next((r for k, r in SKIP.items() if cmd.startswith(k)), None)
            if why:
                skipped += 1
                print(f"skip README:{line}: {cmd.splitlines()[0]} ({why})")
                continue
            ran += 1
            p = subprocess.run(["bash", "-c", cmd], cwd=work, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, timeout=600)
            got = p.stdout.decode("utf-8", "replace").rstrip("\n").split("\n")
            if got == [""]:
                got = []
            while exp and exp[-1].strip() == "":
                exp = exp[:-1]
            if matches(exp, got) or matches_any_layout(exp, got):
                print(f"ok README:{line}: {cmd.splitlines()[0]}")
            elif update and not any(e.strip() == "..." or "…" in e for e in exp):
                # (the README's own lines, indented as they were)
                pad = "    " if text[line - 1].startswith("    $ ") else ""
                edits.append((first, len(exp), [pad + g for g in got]))
                print(f"updated README:{line}: {cmd.splitlines()[0]}")
            else:
                fails += 1
                print(f"FAILED README:{line}: {cmd.splitlines()[0]}")
                print("  README says:\n" + "\n".join("    " + e for e in exp))
                print("  the app says:\n" + "\n".join("    " + g for g in got))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if edits:
        for first, n, new in sorted(edits, reverse=True):
            text[first:first + n] = new
        with open(readme, "w", encoding="utf-8") as f:
            f.write("\n".join(text))
    print(f"{ran - fails} passed, {fails} failed, {skipped} skipped")
    return 1 if fails or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
