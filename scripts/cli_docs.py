#!/usr/bin/env python3
"""docs/cli.md's `--help` blocks, from the binary itself, so the page and the program cannot
drift: every command that `wavefront --help` lists has a block between
<!-- help:COMMAND --> and <!-- /help:COMMAND --> holding `wavefront COMMAND --help` verbatim.

    scripts/cli_docs.py build/wavefront docs/cli.md           check: list every difference, exit 1
    scripts/cli_docs.py build/wavefront docs/cli.md --write   rewrite the blocks in place
"""
import re
import subprocess
import sys


def help_text(binary, command=None):
    args = [binary] + ([command] if command else []) + ["--help"]
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout.rstrip("\n")


def commands(binary):
    text = help_text(binary)
    block = text.split("Commands:", 1)[1].split("\n\n", 1)[0]
    return [line.split()[0] for line in block.splitlines() if line.strip()]


def block(command, text):
    return f"<!-- help:{command} -->\n```\n{text}\n```\n<!-- /help:{command} -->"


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    binary, page, write = sys.argv[1], sys.argv[2], "--write" in sys.argv[3:]
    with open(page, encoding="utf-8") as f:
        doc = f.read()
    problems = []
    for command in ["wavefront"] + commands(binary):
        name = None if command == "wavefront" else command
        expected = block(command, help_text(binary, name))
        pattern = re.compile(rf"<!-- help:{re.escape(command)} -->.*?<!-- /help:{re.escape(command)} -->",
                             re.S)
        found = pattern.search(doc)
        if not found:
            problems.append(f"{page}: no block for `{command}` (<!-- help:{command} -->)")
            continue
        if found.group(0) != expected:
            if write:
                doc = doc[:found.start()] + expected + doc[found.end():]
            else:
                old = found.group(0).splitlines()
                new = expected.splitlines()
                for i in range(max(len(old), len(new))):
                    a = old[i] if i < len(old) else "(nothing)"
                    b = new[i] if i < len(new) else "(nothing)"
                    if a != b:
                        problems.append(f"{page}: `{command}` differs from its --help at line "
                                        f"{i + 1} of the block:\n  page: {a}\n  help: {b}")
                        break
    if write:
        with open(page, "w", encoding="utf-8") as f:
            f.write(doc)
        print(f"cli_docs: wrote the --help blocks of {page}")
        return 0
    for problem in problems:
        print(problem)
    if problems:
        print(f"cli_docs: {len(problems)} difference(s); run scripts/cli_docs.py {binary} {page} --write")
        return 1
    print(f"cli_docs: every command's --help is in {page}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
