#!/bin/sh
# Refreshes the user guide's pictures (resources/help/pictures) from the screenshots the GUI tests keep in
# build/default/test-output: run the GUI tests first (ctest -L gui under xvfb-run), then this script. The English
# interface's pictures come from several tests; the German and Chinese ones (pictures/<code>/) from the walk's
# pass in each language (tst_gui_walk: test-output/gui-walk/guide-<code>) and from tst_gui_drug (the territory)
# and tst_gui_pacs (the PACS dialogs) in each language, which the guides in those languages show.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
shots="$root/build/default/test-output"
/usr/bin/python3 - "$shots" "$root/resources/help/pictures" <<'PY'
import os
import sys
from PIL import Image
shots, out = sys.argv[1], sys.argv[2]
pictures = {'gui/dicom-import-dialog.png': 'import.png', 'gui/vessels.png': 'vessels.png',
            'gui/run-player-wall-mid.png': 'wall-stress.png', 'gui-vessel-view/vessel-view.png': 'vessel-view.png',
            'gui-measure/ruler.png': 'ruler.png', 'gui-drug/screenshot/drug.png': 'drug.png',
            'gui-drug/territory/territory.png': 'territory.png', 'gui/slice-overlays-x1.png': 'slice-view.png',
            'gui-endoscope/endoscope-focused.png': 'endoscope.png', 'gui/pacs-dialog.png': 'pacs.png',
            'gui/pacs-send.png': 'pacs-send.png'}
for code in ('de', 'zh_CN'):
    for name in ('vessels', 'slice-view', 'import', 'wall-stress', 'vessel-view', 'endoscope', 'drug', 'ruler'):
        pictures[f'gui-walk/guide-{code}/{name}.png'] = f'{code}/{name}.png'
    pictures[f'gui-drug/territory-{code}/territory.png'] = f'{code}/territory.png'
    pictures[f'gui/pacs-dialog-{code}.png'] = f'{code}/pacs.png'
    pictures[f'gui/pacs-send-{code}.png'] = f'{code}/pacs-send.png'
for source, name in pictures.items():
    picture = Image.open(f'{shots}/{source}').convert('RGB')
    if picture.width > 900:
        picture = picture.resize((900, picture.height * 900 // picture.width), Image.LANCZOS)
    os.makedirs(os.path.dirname(f'{out}/{name}'), exist_ok=True)
    picture.save(f'{out}/{name}', optimize=True)
    print(name, picture.size)
PY
