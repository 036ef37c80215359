#!/usr/bin/env python3
"""Reads `vascusim-cli parameters --json` on stdin and writes, on stdout, the C++ file lupdate reads for the
parameter tables' texts (translations/ParameterTexts.cpp): each label, group and description once, in the context
"vsim::Parameters" that gui::parameterText looks them up in."""
import json
import sys

texts = []
for table in json.load(sys.stdin):
    for parameter in table["parameters"]:
        for field in ("group", "label", "description"):
            if parameter[field] and parameter[field] not in texts:
                texts.append(parameter[field])

print("// Not compiled: lupdate's source for the parameter tables' labels, groups and descriptions (Parameters.h),")
print("// which live in libraries without Qt. Written by scripts/update-translations.sh from the parameter catalogue;")
print("// do not edit. gui::parameterText looks them up at run time.")
print("static const char* const kParameterTexts[] = {")
for text in texts:
    print("    QT_TRANSLATE_NOOP(\"vsim::Parameters\", %s)," % json.dumps(text, ensure_ascii=False))
print("};")
