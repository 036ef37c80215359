#!/usr/bin/env python3
"""Writes, on stdout, translations/ErrorTexts.cpp: the libraries' texts for people, for lupdate and compiled into
vsim_core. Every vsim::Error message written as one string literal (adjacent literals joined) or as a pattern with
its values apart (Pattern{"... %1 ...", {values}}), every context key written as a literal, and every stored text
(storedText("literal"), core StoredText.h), in the context "vsim::Error" that Error::textForPeople() and
storedTextForPeople() look them up in (the latter also matches stored English against the list). Messages
concatenated at run time are not found and stay English. With --check FILE: exit 1 when FILE is not what would be
written (tst_error_texts_current).
usage: error_texts.py [--check FILE]   (from the repository root)"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
# The code a person's messages come from; the CLI's own messages (usage, options) stay English, as its options do.
SOURCES = ["modules", "cuda", "app/common", "app/gui"]
# Where only stored texts are read: what the CLI writes into a study is read in the workstation too.
STORED_ONLY = ["app/cli"]
LITERAL = r'"(?:[^"\\]|\\.)*"'
CALL = re.compile(r"\bError\s*\(")
STORED = re.compile(r"\bstoredText\s*\(\s*((?:" + LITERAL + r"\s*)+)\)")  # storedText("literal")
PATTERN = re.compile(r"\bPattern\s*\{\s*((?:" + LITERAL + r"\s*)+),")  # Error(Pattern{"... %1 ...", {values}})


def arguments_at(text, start):
    """The text between the parenthesis before `start` and its partner."""
    depth, i, in_string = 1, start, False
    while depth and i < len(text):
        c = text[i]
        if in_string:
            if c == "\\":
                i += 1
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
        elif c in "({[":
            depth += 1
        elif c in ")}]":
            depth -= 1
        i += 1
    return text[start:i - 1]


def texts():
    found = []
    def files(folders):
        return sorted(p for folder in folders for p in (ROOT / folder).rglob("*")
                      if p.suffix in (".cpp", ".h", ".cu", ".cuh"))
    for path in files(SOURCES + STORED_ONLY):
        text = path.read_text(encoding="utf-8")
        stored_only = any(path.is_relative_to(ROOT / folder) for folder in STORED_ONLY)
        for pattern in PATTERN.finditer(text):
            if stored_only and not re.search(r"storedText\s*\(\s*$", text[:pattern.start()]):
                continue
            found.append("".join(part[1:-1] for part in re.findall(LITERAL, pattern.group(1))))
        for stored in STORED.finditer(text):
            found.append("".join(part[1:-1] for part in re.findall(LITERAL, stored.group(1))))
        if stored_only:
            continue
        for call in CALL.finditer(text):
            arguments = arguments_at(text, call.end())
            message = re.match(r"\s*((?:" + LITERAL + r"\s*)+)(?=,|$)", arguments)
            if message:
                found.append("".join(part[1:-1] for part in re.findall(LITERAL, message.group(1))))
            found.extend(re.findall(r'\{\s*"([a-z_ ]+)"\s*,', arguments))  # context keys
    unique = []
    for text in found:
        if text and text not in unique:
            unique.append(text)
    return unique


def written():
    lines = ["// The libraries' texts for people: error messages and context keys (core Error.h) and stored texts (core",
             "// StoredText.h), which live in code without Qt. lupdate's source, and compiled into vsim_core for",
             "// storedTextForPeople(). Written by scripts/update-translations.sh (scripts/error_texts.py) from every",
             "// vsim::Error(\"literal\", {{\"key\", ...}}), Pattern{\"... %1 ...\", ...} and storedText(\"literal\") in",
             "// modules/, cuda/, app/common and app/gui (app/cli: stored texts only); do not edit.",
             "#include <cstddef>",
             "",
             "#ifndef QT_TRANSLATE_NOOP",
             "#define QT_TRANSLATE_NOOP(context, text) text",
             "#endif",
             "",
             "namespace vsim::detail {",
             "extern const char* const kLibraryTexts[];",
             "extern const std::size_t kLibraryTextCount;",
             "const char* const kLibraryTexts[] = {"]
    lines += ['    QT_TRANSLATE_NOOP("vsim::Error", "%s"),' % text for text in texts()]
    lines += ["};", "const std::size_t kLibraryTextCount = sizeof(kLibraryTexts) / sizeof(kLibraryTexts[0]);",
              "} // namespace vsim::detail"]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        current = pathlib.Path(sys.argv[2]).read_text(encoding="utf-8")
        if current != written():
            print(sys.argv[2] + " is not current: run scripts/update-translations.sh and translate", file=sys.stderr)
            sys.exit(1)
        print(sys.argv[2] + ": current, %d texts" % len(texts()))
    else:
        sys.stdout.write(written())
