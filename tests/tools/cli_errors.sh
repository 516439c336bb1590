#!/usr/bin/env bash
# The command's error contract from outside: each failure is one line on stderr naming the
# file or glyph, exit code 2 (3 for an unwritable output), and no output left behind.
set -u
glyphfair=$1 fonts=$2 work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
dejavu=$fonts/DejaVuSans/DejaVuSans-subset.ttf
inter=$fonts/Inter/Inter-subset.var.ttf
head -c 20000 "$dejavu" > truncated.ttf
echo "plain text" > text.ttf
failures=0 passed=0

expect() {  # expect CODE PATTERN ARGS...
  local code=$1 pattern=$2; shift 2
  rm -rf out.ufo out.pdf out.svg
  "$glyphfair" "$@" 2>err.txt >/dev/null
  local rc=$? lines
  lines=$(wc -l < err.txt)
  if [[ $rc -ne $code ]] || [[ $lines -ne 1 ]] || ! grep -q -- "$pattern" err.txt || compgen -G 'out.*' >/dev/null || compgen -G '.out.*' >/dev/null; then
    echo "FAIL: glyphfair $* -> exit $rc, $lines line(s): $(cat err.txt) $(ls -a | grep out)"
    failures=$((failures + 1))
  else
    passed=$((passed + 1))
  fi
}

expect 2 "missing.ttf: no such file" convert missing.ttf -o out.ufo
expect 2 "text.ttf: not a font file" convert text.ttf -o out.ufo
expect 2 "truncated.ttf: truncated font" convert truncated.ttf -o out.ufo
expect 2 "glyph 'nosuch': no glyph of that name" convert "$dejavu" --glyphs a,nosuch -o out.ufo
expect 2 "glyph 'nosuch': no glyph of that name" proof "$dejavu" --glyphs nosuch -o out.pdf
expect 2 "U+10FFFF: no glyph" convert "$dejavu" --unicodes U+10FFFF -o out.svg
expect 2 "'U+00ZZ' is not a hexadecimal" convert "$dejavu" --unicodes U+00ZZ -o out.ufo
expect 2 "ends before it starts" convert "$dejavu" --unicodes 5A-41 -o out.ufo
expect 2 "'wght700' is not of the form" convert "$inter" --location wght700 -o out.ufo
expect 2 "outside the axis range" convert "$inter" --location wght=1200 -o out.ufo
expect 2 "no axis 'wdth'" convert "$inter" --location wdth=80 -o out.ufo
expect 2 "needs a variable font" convert "$dejavu" --location wght=700 -o out.ufo
expect 2 "no named instance 'Nope'" convert "$inter" --instance Nope -o out.ufo
expect 2 "unknown output format" convert "$dejavu" -o out.xyz
expect 2 "not valid UTF-8" convert "$dejavu" --text $'\xff\xfe' -o out.ufo
expect 3 "does not exist" convert "$dejavu" -o no/such/dir/out.ufo
"$glyphfair" convert "$dejavu" --glyphs a -o in.ufo
cp -r in.ufo before.ufo
expect 3 "refusing to overwrite an input" convert in.ufo -o in.ufo
diff -r in.ufo before.ufo >/dev/null || { echo "FAIL: the input was changed"; failures=$((failures + 1)); }

echo "$passed passed, $failures failed"
((failures == 0))
