#!/usr/bin/env bash
# The text bars of the fairing issue over 44 text fonts from Debian's packages, a–z A–Z:
# each font faired by GLYPHFAIR (one glyph job each, two fonts at a time), then measured by
# tests/tools/fairing_bars.py. Writes OUTDIR/NAME.ufo, NAME.err, NAME.bars.txt and NAME.json,
# and prints a line per font. Compare two builds with scripts/sweep_diff.py OLD NEW.
#
# The fonts come from these packages (not installed by scripts/dev.sh):
#   fonts-dejavu-core fonts-crosextra-caladea fonts-crosextra-carlito fonts-freefont-otf
#   fonts-sil-gentiumplus fonts-linuxlibertine fonts-noto-core fonts-texgyre fonts-comic-neue
#   fonts-ebgaramond fonts-lato fonts-inter fonts-roboto-unhinted fonts-liberation2
#   fonts-cantarell fonts-open-sans fonts-inconsolata fonts-hack fonts-go fonts-jetbrains-mono
#   fonts-quicksand fonts-oxygen fonts-cabin fonts-junicode fonts-stix fonts-vollkorn
#   fonts-league-spartan fonts-adf-accanthis fonts-urw-base35
#
# usage: scripts/text_sweep.sh GLYPHFAIR OUTDIR [PATTERN]   (PATTERN: only the fonts whose path matches)
set -euo pipefail
(($# == 2 || $# == 3)) || { echo "usage: $0 GLYPHFAIR OUTDIR [PATTERN]" >&2; exit 2; }
bin=$(realpath "$1"); out=$2; pattern=${3:-.}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
s=/usr/share/fonts; g=/usr/share/texmf/fonts/opentype/public/tex-gyre
fonts=(
  $s/truetype/dejavu/DejaVuSans.ttf $s/truetype/dejavu/DejaVuSerif.ttf $s/truetype/dejavu/DejaVuSansMono.ttf
  $s/truetype/crosextra/Caladea-Regular.ttf $s/truetype/crosextra/Carlito-Regular.ttf
  $s/opentype/freefont/FreeSerif.otf $s/opentype/freefont/FreeSans.otf $s/opentype/freefont/FreeMono.otf
  $s/truetype/gentiumplus/GentiumPlus-Regular.ttf
  $s/opentype/linux-libertine/LinLibertine_R.otf $s/opentype/linux-libertine/LinBiolinum_R.otf
  $s/truetype/noto/NotoSans-Regular.ttf $s/truetype/noto/NotoSerif-Regular.ttf
  $g/texgyrepagella-regular.otf $g/texgyreheros-regular.otf $g/texgyrebonum-regular.otf
  $g/texgyretermes-regular.otf $g/texgyreschola-regular.otf $g/texgyreadventor-regular.otf
  $s/opentype/comic-neue/ComicNeue-Regular.otf $s/opentype/ebgaramond/EBGaramond12-Regular.otf
  $s/truetype/lato/Lato-Regular.ttf $s/opentype/inter/Inter-Regular.otf
  $s/truetype/roboto/unhinted/RobotoTTF/Roboto-Regular.ttf
  $s/truetype/liberation2/LiberationSans-Regular.ttf $s/truetype/liberation2/LiberationSerif-Regular.ttf
  $s/truetype/liberation2/LiberationMono-Regular.ttf
  $s/opentype/cantarell/Cantarell-Regular.otf $s/truetype/open-sans/OpenSans-Regular.ttf
  $s/truetype/inconsolata/Inconsolata.otf $s/truetype/hack/Hack-Regular.ttf $s/fonts-go/Go-Regular.ttf
  $s/truetype/jetbrains-mono/JetBrainsMono-Regular.ttf $s/truetype/quicksand/Quicksand-Regular.ttf
  $s/truetype/oxygen/Oxygen-Sans.ttf $s/opentype/cabin/Cabin-Regular.otf
  $s/opentype/junicode/JunicodeTwoBeta-Regular.otf $s/opentype/stix/STIXGeneral-Regular.otf
  $s/truetype/vollkorn/Vollkorn-Regular.ttf $s/opentype/league-spartan/LeagueSpartan-Regular.otf
  $s/truetype/adf/AccanthisADFStd-Regular.otf
  $s/opentype/urw-base35/NimbusRoman-Regular.otf $s/opentype/urw-base35/C059-Roman.otf
  $s/opentype/urw-base35/P052-Roman.otf
)
letters=abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ

# A line per font: PASS, FAIL (a bar failed, NAME.bars.txt says which) or ERROR (glyphfair
# failed, NAME.err says why).
one() {
  local font=$1 name; name=$(basename "${font%.*}")
  if ! "$bin" fair "$font" --text "$letters" --profile text --jobs 1 -o "$out/$name.ufo" 2>"$out/$name.err"; then
    echo "ERROR $name"; return
  fi
  local verdict=FAIL
  /usr/bin/python3 "$here/tests/tools/fairing_bars.py" "$font" "$out/$name.ufo" --profile text \
    --json "$out/$name.json" >"$out/$name.bars.txt" 2>&1 && verdict=PASS
  echo "$verdict $name"
}
export -f one; export bin out here letters
printf '%s\n' "${fonts[@]}" | grep -E -- "$pattern" | xargs -P 2 -I{} bash -c 'one "$@"' _ {} | sort -k2
