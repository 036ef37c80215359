#!/usr/bin/env python3
"""Checks the report's languages (issue 20, item 7) on a study's reports made with --language:

- the pseudo-locale report (pseudo_catalogue.py: every catalogue text comes back as «text»): once the bracketed
  texts are taken out, no English word is left but the study's own data (names, descriptions, the runs' recorded
  warnings and parameters, as study.json keeps them) and unit symbols: a text the report writes without the
  catalogues fails here;
- the German and the Chinese report: no source sentence (four words or more) of the catalogue whose translation
  differs is left in English: a catalogue entry the report does not apply fails here; the report's title is
  in that language; and its figures with a unit carry the language's decimal mark (German 3,5 mm; Chinese and
  the pseudo-locale 3.5 mm).

usage: check_report_language.py STUDY_BUNDLE PSEUDO_PDF GERMAN_PDF GERMAN_TS CHINESE_PDF CHINESE_TS"""

import json
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

# Symbols and names that read the same in every language.
UNIVERSAL = {"mmHg", "nats", "VascuSim", "TAWSS", "vascusim", "LAO", "RAO", "LPS", "SVS", "DICOM"}


def fail(message):
    print("check_report_language: " + message, file=sys.stderr)
    sys.exit(1)


def text_of(pdf):
    text = subprocess.run(["pdftotext", "-raw", pdf, "-"], check=True, capture_output=True, text=True).stdout
    return re.sub(r"\s+", " ", text)


def study_words(bundle):
    """Every word of the study's own records: what the report may print as data."""
    words = set()

    def walk(value):
        if isinstance(value, dict):
            for item in value.values():  # the keys are the program's, not data a reader sees
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)
        elif isinstance(value, str):
            words.update(re.findall(r"[A-Za-z]+", value))

    walk(json.load(open(bundle + "/study.json", encoding="utf-8")))
    return words


def catalogue(ts):
    """(source, translation) of every finished entry."""
    pairs = []
    for message in ET.parse(ts).getroot().iter("message"):
        translation = message.find("translation")
        if translation.get("type") != "unfinished" and translation.text and translation.text.strip():
            pairs.append((message.find("source").text, translation.text))
    return pairs


def check_pseudo(bundle, pdf):
    text = text_of(pdf)
    if "\u00ab" not in text:
        fail(pdf + ": the pseudo-locale catalogue was not applied")
    outside, previous = text, None
    while outside != previous:  # innermost first: a text may hold another ("«%1: not rendered»" around a caption)
        previous, outside = outside, re.sub("\u00ab[^\u00ab\u00bb]*\u00bb", " ", outside)
    outside = re.sub(r"--[a-z][a-z-]*", " ", outside)  # command-line options (the Command row) are the program's
    allowed = study_words(bundle) | UNIVERSAL
    stray = sorted({word for word in re.findall(r"[A-Za-z]{4,}", outside) if word not in allowed})
    if stray:
        contexts = [outside[max(0, outside.find(w) - 60):outside.find(w) + 60] for w in stray[:5]]
        fail(pdf + ": words outside the catalogues: " + ", ".join(stray) + "\n  " + "\n  ".join(contexts))
    return len(re.findall("\u00ab", text))


def check_decimal_mark(pdf, text, mark):
    """Every figure printed with decimals and a unit uses `mark`; there is at least one."""
    figures = re.findall(r"(?<![\d.,])\d+([.,])\d+ ?(?:kPa|MPa|mmHg|mm|ml|Pa|cm/s|m/s|s|%)(?![A-Za-z])", text)
    if not figures:
        fail(pdf + ": no figure with decimals and a unit found")
    wrong = [f for f in figures if f != mark]
    if wrong:
        samples = re.findall(r"(?<![\d.,])\d+[" + ("." if mark == "," else ",") + r"]\d+ ?[A-Za-z%/]+", text)[:5]
        fail(pdf + ": %d of %d figures without the decimal mark '%s': %s" % (len(wrong), len(figures), mark, samples))
    return len(figures)


def check_translated(pdf, ts, title, mark):
    text = text_of(pdf)
    if title not in text:
        fail(pdf + ": the title '" + title + "' is missing")
    check_decimal_mark(pdf, text, mark)
    left = []
    for source, translation in catalogue(ts):
        sentence = re.sub(r"\s+", " ", source).strip()
        if translation != source and len(sentence.split()) >= 4 and "%" not in sentence and sentence in text:
            left.append(sentence)
    if left:
        fail(pdf + ": English left where the catalogue has a translation:\n  " + "\n  ".join(left[:10]))


def main():
    bundle, pseudo, german, german_ts, chinese, chinese_ts = sys.argv[1:7]
    marked = check_pseudo(bundle, pseudo)
    figures = check_decimal_mark(pseudo, text_of(pseudo), ".")
    check_translated(german, german_ts, "VascuSim-Planungsbericht", ",")
    check_translated(chinese, chinese_ts, "VascuSim 规划报告", ".")
    print(f"{bundle}: {marked} texts from the catalogues, none outside them; German and Chinese applied; "
          f"{figures} figures with the decimal mark of each language")


if __name__ == "__main__":
    main()
