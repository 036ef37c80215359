#!/usr/bin/env bash
# Brings translations/*.ts up to date with the sources: writes translations/ParameterTexts.cpp from the parameter
# catalogue (`vascusim-cli parameters --json`: labels, groups and descriptions that live outside Qt code) and
# translations/ErrorTexts.cpp from the libraries' error messages (scripts/error_texts.py), then runs lupdate over
# the GUI, the views and those files. New texts come in "unfinished": translate them in Qt Linguist
# (or the .ts directly); tst_translations fails until none is left.
#   scripts/update-translations.sh [build-dir]   (default build/default, built)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/default}"
DCMDICTPATH="$(ls /usr/share/libdcmtk*/dicom.dic | head -1)" "$build/bin/vascusim-cli" parameters --json |
    python3 scripts/parameter_texts.py > translations/ParameterTexts.cpp
python3 scripts/error_texts.py > translations/ErrorTexts.cpp
cmake --build "$build" --target update_translations
