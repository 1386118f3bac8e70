#!/usr/bin/env python3
"""A sentence of six words or more said twice in one page of README.md or paper/*.md (outside code
blocks, display formulas, tables, headings and list items) is a leftover of an edit: prints each with
its page and exits 1. (README.md once said twice that scenes/dyka_bar.toml is a complete example.)

    tests/docs_prose.py FILE.md ...
"""
import collections
import re
import sys


def sentences(text):
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    text = re.sub(r"\\f\[.*?\\f\]", "", text, flags=re.S)
    found = []
    for paragraph in re.split(r"\n\s*\n", text):
        lines = [l.strip() for l in paragraph.split("\n") if not l.lstrip().startswith(("|", "#", "<!--", "- ", "* "))]
        for sentence in re.split(r"(?<=[.;:])\s+(?=[A-Z`(])", " ".join(lines)):
            sentence = sentence.strip().rstrip(".;:")
            if len(sentence.split()) >= 6:
                found.append(sentence)
    return found


def main(files):
    repeated = 0
    for path in files:
        for sentence, count in collections.Counter(sentences(open(path).read())).items():
            if count > 1:
                print(f"{path}: said {count} times: {sentence}")
                repeated += 1
    return 1 if repeated else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
