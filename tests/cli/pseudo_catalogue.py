#!/usr/bin/env python3
"""Writes the pseudo-locale catalogue (issue 20, item 7): every text of a translation source (.ts) comes back as
«source», so that a report made with it shows which of its words went through the catalogues and which did not.

usage: pseudo_catalogue.py SOURCE.ts OUT.ts"""

import sys
import xml.etree.ElementTree as ET


def main():
    source, out = sys.argv[1], sys.argv[2]
    tree = ET.parse(source)
    for message in tree.getroot().iter("message"):
        translation = message.find("translation")
        translation.attrib.pop("type", None)
        marked = "\u00ab" + message.find("source").text + "\u00bb"
        forms = translation.findall("numerusform")
        for form in forms:  # plural forms: each one marked
            form.text = marked
        if not forms:
            translation.text = marked
    tree.getroot().set("language", "en_ZZ")
    tree.write(out, encoding="utf-8", xml_declaration=True)


if __name__ == "__main__":
    main()
