"""Every `tendril` command the documentation shows names a command that exists and only options
that command takes, as docs/cli.md (generated from the program's command table, and tested to be
current) lists them. A page that still shows a renamed or removed option fails here.

    python3 tests/docs/commands_test.py <source dir>
"""
import pathlib
import re
import shlex
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
PROGRAM = re.compile(r"(?:^|[\s`(])(?:build(?:-lite)?/apps/)?tendril\s+(.*)")
# Where a shell command ends: pipes, lists, redirections, comments.
END = re.compile(r"\s(?:\||&&|;|2?>>?|<|#)\s|\s(?:2>&1|&)\s*$|\s#.*$")


def commands_and_options():
    """{("train",): {"--set", "-o", "--output", ...}, ("sweep", "run"): {...}, ...}"""
    table = {}
    text = (ROOT / "docs/cli.md").read_text()
    for section in re.split(r"^## tendril ", text, flags=re.M)[1:]:
        words = tuple(section.splitlines()[0].split())
        options = set(re.findall(r"^  (?:(-\w), )?(--[\w-]+)", section, flags=re.M))
        table[words] = {name for pair in options for name in pair if name} | {"-h", "--help"}
    return table


def shown_commands(page):
    """(line number, command text) of every tendril command in a page's code: indented or
    fenced blocks (continuation lines joined) and inline code spans."""
    lines = page.read_text().splitlines()
    fenced = False
    previous_blank, in_block = True, False
    k = 0
    while k < len(lines):
        line = lines[k]
        if line.lstrip().startswith("```"):
            fenced = not fenced
            previous_blank, in_block = False, False
            k += 1
            continue
        # An indented code block follows a blank line (or continues one); an indented line after
        # text continues a list item.
        indented = line.startswith("    ") or line.startswith("\t")
        block = fenced or (indented and (previous_blank or in_block))
        in_block = block and not fenced
        previous_blank = not line.strip()
        if block and line.lstrip().startswith("#"):
            k += 1
            continue  # a shell comment
        spans = [line] if block else re.findall(r"`([^`]*)`", line)
        start = k
        if block:
            while spans[0].rstrip().endswith("\\") and k + 1 < len(lines):
                k += 1
                spans[0] = spans[0].rstrip()[:-1] + " " + lines[k].strip()
        for span in spans:
            for match in PROGRAM.finditer(span):
                yield start + 1, match.group(1), block
        k += 1


def tokens(text):
    text = END.split(" " + text + " ", maxsplit=1)[0]
    try:
        return shlex.split(text, posix=True)
    except ValueError:  # an unbalanced quote in an abbreviated span
        return text.split()


def is_number(token):
    """A value, not an option: -3, -0.5, -56.9,0,60."""
    return re.fullmatch(r"-[0-9.][0-9.,e+-]*", token) is not None


def check(page, table, problems):
    verbs = {words[0] for words in table}
    for line, text, block in shown_commands(page):
        args = tokens(text)
        if not args or not re.fullmatch(r"[a-z][a-z-]*", args[0]):
            continue  # not a command: prose ("tendril's …") or a placeholder ("<verb>")
        if args[0] not in verbs:
            # Prose that starts with the program's name ("tendril trains …") is not a command;
            # a code block's line is.
            if block:
                problems.append(f"{page}:{line}: no command '{args[0]}': tendril {text}")
            continue
        words = (args[0],) if (args[0],) in table else tuple(args[:2])
        if words not in table:
            if len(args) > 1 and not args[1].startswith("-") and args[1] not in ("…", "...", "<verb>"):
                problems.append(f"{page}:{line}: no command '{' '.join(words)}': tendril {text}")
            continue
        if words == ("plot",):
            continue  # its own parser (python -m tendril_plot), checked by its tests
        for arg in args[len(words):]:
            if not arg.startswith("-") or is_number(arg) or arg in ("-", "--", "…", "..."):
                continue
            name = arg.split("=", 1)[0]
            if name not in table[words]:
                problems.append(
                    f"{page}:{line}: tendril {' '.join(words)} has no option {name}: tendril {text}")


def main():
    table = commands_and_options()
    assert ("train",) in table and ("model", "eval") in table, "docs/cli.md has no command table"
    pages = [ROOT / "README.md"] + sorted((ROOT / "docs").rglob("*.md"))
    pages = [p for p in pages if p.name != "cli.md"]
    problems = []
    for page in pages:
        check(page, table, problems)
    for problem in problems:
        print(problem)
    print(f"{len(problems)} problems in {len(pages)} pages ({len(table)} commands)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
