#!/usr/bin/env python3
"""The README and the manual hold: every relative link and image resolves to a file of the repository, every
#anchor to a heading (or an <a id>) of the page it names, and every `rosin ...` command of a fenced shell block
is accepted by that subcommand's parser (`rosin --parse-only`).

Usage: check_docs.py --root REPO [--rosin build/rosin]; exit status 1 with one line per problem. Without
--rosin only the links are checked. Links to other sites are not followed (CI has no network).
"""
import argparse
import os
import re
import shlex
import subprocess
import sys

FENCE = re.compile(r"^(\s*)(```|~~~)(.*)$")
LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
HTML_ID = re.compile(r"<a\s+(?:id|name)=\"([^\"]+)\"")
SHELL = {"", "sh", "bash", "shell", "console"}


def pages(root):
    yield os.path.join(root, "README.md")
    docs = os.path.join(root, "Resources", "docs")
    for name in sorted(os.listdir(docs)):
        if name.endswith(".md"):
            yield os.path.join(docs, name)


def split_fences(text):
    """(prose lines with their numbers, [(language, first line number, code lines)])."""
    prose, blocks, block = [], [], None
    for number, line in enumerate(text.splitlines(), 1):
        fence = FENCE.match(line)
        if block is None and fence:
            block = (fence.group(3).strip().lower(), number + 1, [])
        elif block is not None and fence and not fence.group(3).strip():
            blocks.append(block)
            block = None
        elif block is not None:
            block[2].append(line)
        else:
            prose.append((number, line))
    return prose, blocks


def slug(heading):
    """GitHub's anchor for a heading: lower case, markup and punctuation dropped, spaces to hyphens."""
    text = re.sub(r"`|\*\*|\*|_(?=\w)|(?<=\w)_", "", heading.strip().lower())
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        prose, _ = split_fences(open(path, encoding="utf-8").read())
        found, seen = set(), {}
        for _, line in prose:
            found.update(HTML_ID.findall(line))
            heading = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
            if heading:
                base = slug(heading.group(1))
                n = seen.get(base, 0)
                seen[base] = n + 1
                found.add(base if n == 0 else "%s-%d" % (base, n))
        cache[path] = found
    return cache[path]


def check_links(root, page, problems):
    prose, _ = split_fences(open(page, encoding="utf-8").read())
    where = os.path.relpath(page, root)
    for number, line in prose:
        line = re.sub(r"`[^`]*`", "", line)  # inline code is not a link
        for target in LINK.findall(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # https:, mailto:
                continue
            path, _, anchor = target.partition("#")
            resolved = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not resolved.startswith(os.path.abspath(root)) or not os.path.exists(resolved):
                problems.append("%s:%d: link to %s: no such file" % (where, number, target))
            elif anchor:
                if not resolved.endswith(".md"):
                    problems.append("%s:%d: link to %s: an anchor into a file that is not a page" % (where, number, target))
                elif anchor not in anchors(resolved):
                    problems.append("%s:%d: link to %s: no heading or <a id> \"%s\" in %s"
                                    % (where, number, target, anchor, os.path.relpath(resolved, root)))


def shell_commands(code):
    """The commands of a shell block: continuations joined, comments dropped, split at && ; |."""
    joined = re.sub(r"\\\n\s*", " ", "\n".join(code))
    for line in joined.splitlines():
        try:
            words = shlex.split(line, comments=True)
        except ValueError:
            yield None, line
            continue
        command = []
        for word in words + ["&&"]:
            if word in ("&&", "||", ";", "|"):
                if command:
                    yield command, line
                command = []
            else:
                command.append(word)


def rosin_arguments(words):
    """The arguments after the rosin executable ("rosin", "./build/rosin", under mpirun), or None."""
    for i, word in enumerate(words):
        if os.path.basename(word) == "rosin":
            return words[i + 1:]
        if word not in ("mpirun", "sudo") and not word.startswith("-") and not word.isdigit():
            return None
    return None


def check_commands(root, page, rosin, problems):
    _, blocks = split_fences(open(page, encoding="utf-8").read())
    where = os.path.relpath(page, root)
    for language, first, code in blocks:
        if language not in SHELL:
            continue
        for words, line in shell_commands(code):
            if words is None:
                if re.search(r"(^|[\s/])rosin\s", line):
                    problems.append("%s:%d: cannot read the shell line %r" % (where, first, line))
                continue
            args = rosin_arguments(words)
            if args is None or not args or args[0].startswith("-"):
                continue  # not rosin, or rosin --help / --version
            done = subprocess.run([rosin, "--parse-only"] + args, capture_output=True, text=True, cwd=root)
            if done.returncode != 0:
                problems.append("%s:%d: `rosin %s` is refused: %s" % (where, first, " ".join(args),
                                                                     done.stderr.strip().splitlines()[0]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True)
    parser.add_argument("--rosin")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    rosin = os.path.abspath(args.rosin) if args.rosin and os.sep in args.rosin else args.rosin
    problems, count = [], 0
    for page in pages(root):
        count += 1
        check_links(root, page, problems)
        if rosin:
            check_commands(root, page, rosin, problems)
    for p in problems:
        print(p)
    if problems:
        print("%d problem(s) in the README and the manual" % len(problems))
        return 1
    print("%d pages: every link, anchor, image%s holds" % (count, " and rosin command" if args.rosin else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
