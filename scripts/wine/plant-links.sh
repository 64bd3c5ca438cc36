#!/usr/bin/env bash
# Plants the links of issue 59's attacks in the folder $1 (made fresh), one folder each,
# with the Linux phonglab $2 (optional) writing the set f2's link replaces,
# for the tests of links (tests/all/set_links.rs, src/platform/links.rs). On Linux a test
# runs it itself; under Wine the tests cannot make a link (Wine 8's CreateSymbolicLinkW
# makes none), so scripts/test-windows runs it on the Linux side before the Windows tests
# and names the folder in PHONGLAB_PLANTED_LINKS.
#   f1: an oF project whose src/ofApp.h is a link to a file outside it (vic/helper.h)
#   f2: an exercise folder whose exercise-01.md is a link to vic/ex.md, outside it (with
#       $2: a set phonglab wrote, whose exercise-01.md was moved to vic/ex.md, a copy of it
#       kept as ex.md.copy, and linked; its list of what it wrote names it as it is)
#   f3: lw, a link to the folder v3 (with a file of the user's, notes.txt)
#   f4: an oF project whose src is a link to the folder v1, outside it
#   f5: an exercise folder whose list of what phonglab wrote is a link to vic/list.txt
#   plain: a file and a folder, no link (what is not refused)
set -euo pipefail
d=$1
rm -rf "$d"
mkdir -p "$d"/f1/vic "$d"/f1/p/src "$d"/f2/vic "$d"/f2/ew "$d"/f3/v3 "$d"/f4/v1 "$d"/f4/ofw "$d"/f5/vic "$d"/f5/ew \
  "$d"/plain/folder
echo helper >"$d"/f1/vic/helper.h
ln -s ../../vic/helper.h "$d"/f1/p/src/ofApp.h
if [ -n "${2:-}" ]; then
  LC_ALL=C.UTF-8 "$2" exercise --count 2 --out "$d"/f2/ew >/dev/null 2>&1
  mv "$d"/f2/ew/exercise-01.md "$d"/f2/vic/ex.md
else
  echo "my exercise" >"$d"/f2/vic/ex.md
fi
cp "$d"/f2/vic/ex.md "$d"/f2/ex.md.copy
ln -s ../vic/ex.md "$d"/f2/ew/exercise-01.md
echo mine >"$d"/f3/v3/notes.txt
ln -s v3 "$d"/f3/lw
ln -s ../v1 "$d"/f4/ofw/src
echo "my list" >"$d"/f5/vic/list.txt
ln -s ../vic/list.txt "$d"/f5/ew/.phonglab-set.written
echo plain >"$d"/plain/file.txt
