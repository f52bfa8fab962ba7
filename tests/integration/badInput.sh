#!/bin/bash
#------------------------------------------------------------------------------
# Bad input to rbdPackBed: one case of badInput.cases (argument: its name).
# Asserts: non-zero exit, the expected error text, the file named, no crash or
# stack trace, and nothing written into the case.
#
# The expected text is a Perl regex (grep -P) matched against the whole log
# at once (-z): '.' stops at a line end, so 'a.*b' needs a and b on one
# line; a pattern that spans lines says so with '(.|\n)*'.
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
name="$1"
line="$(grep -E "^$name[[:space:]]*\|" "$here/badInput.cases")"
[ -n "$line" ] || { echo "no case '$name'"; exit 2; }
action="$(echo "$line" | cut -d'|' -f2 | sed 's/^ *//; s/ *$//')"
expect="$(echo "$line" | cut -d'|' -f3- | sed 's/^ *//; s/ *$//')"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cp -r "$here/cases/smallSpheres" "$tmp/case"
dict="$tmp/case/system/packingDict"
caseArg="$tmp/case"

set -- $action
case "$1" in
    set)    foamDictionary "$dict" -entry "$2" -set "$3" >/dev/null 2>&1 \
                || { echo "foamDictionary -set failed"; exit 2; } ;;
    remove) foamDictionary "$dict" -entry "$2" -remove >/dev/null 2>&1 \
                || { echo "foamDictionary -remove failed"; exit 2; } ;;
    sed)    sed -i "${action#sed }" "$dict" ;;
    nocase) caseArg="$tmp/doesNotExist" ;;
    nodict) rm "$dict" ;;
    stl)    # an STL pellet: 'none' (no file) or 'open' (a tetrahedron
            # missing one face)
            foamDictionary "$dict" -entry pellets/shape -set stl >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/diameter -remove >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/faces -remove >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/file -add '"constant/pellet.stl"' >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/scale -add 0.01 >/dev/null 2>&1
            if [ "$2" = open ]
            then
                mkdir -p "$tmp/case/constant"
                cat > "$tmp/case/constant/pellet.stl" <<'STL'
solid open
facet normal 0 0 -1
outer loop
vertex 0 0 0
vertex 0 1 0
vertex 1 0 0
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex 0 0 0
vertex 1 0 0
vertex 0 0 1
endloop
endfacet
facet normal -1 0 0
outer loop
vertex 0 0 0
vertex 0 0 1
vertex 0 1 0
endloop
endfacet
endsolid open
STL
            elif [ "$2" = fine ]
            then
                # a closed, outward cube of 12 x 130^2 = 202800 triangles
                # (binary), more than pelletShape::maxFaces
                mkdir -p "$tmp/case/constant"
                /usr/bin/python3 - "$tmp/case/constant/pellet.stl" <<'PY'
import struct, sys
n = 130
tris = []
for axis in range(3):
    for side in (0, 1):
        for i in range(n):
            for j in range(n):
                def p(a, b):
                    q = [0.0, 0.0, 0.0]
                    q[axis] = float(side)
                    q[(axis + 1) % 3] = a / n
                    q[(axis + 2) % 3] = b / n
                    return q
                a, b, c, d = p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)
                nrm = [0.0, 0.0, 0.0]
                nrm[axis] = 1.0 if side else -1.0
                if side:
                    tris += [(nrm, a, b, c), (nrm, a, c, d)]
                else:
                    tris += [(nrm, a, c, b), (nrm, a, d, c)]
with open(sys.argv[1], 'wb') as f:
    f.write(b'\0' * 80 + struct.pack('<I', len(tris)))
    for t in tris:
        f.write(struct.pack('<12fH', *(t[0] + t[1] + t[2] + t[3]), 0))
PY
            fi ;;
    casefile) # -case names a file, not a directory
            touch "$tmp/notADirectory"; caseArg="$tmp/notADirectory" ;;
    file)   # a regular file where an output directory goes
            mkdir -p "$(dirname "$tmp/case/$2")"; touch "$tmp/case/$2" ;;
    dir)    # a directory where an output file goes
            mkdir -p "$tmp/case/$2" ;;
    stlnan) # a binary STL tetrahedron with one NaN coordinate
            foamDictionary "$dict" -entry pellets/shape -set stl >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/diameter -remove >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/faces -remove >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/file -add '"constant/pellet.stl"' >/dev/null 2>&1
            foamDictionary "$dict" -entry pellets/scale -add 0.01 >/dev/null 2>&1
            mkdir -p "$tmp/case/constant"
            stl="$tmp/case/constant/pellet.stl"
            # floats, little endian: 0, 1, NaN
            z='\x00\x00\x00\x00'; o='\x00\x00\x80\x3f'; n='\x00\x00\xc0\x7f'
            { printf '%080d' 0 | tr 0 ' '; printf '\x04\x00\x00\x00'
              for tri in "$z$z$z $o$z$z $z$o$z" "$z$z$z $z$z$o $o$z$z" \
                         "$z$z$z $z$o$z $z$z$o" "$o$z$z $n$z$o $z$o$z"
              do
                  printf "$z$z$z"; for v in $tri; do printf "$v"; done
                  printf '\x00\x00'
              done; } > "$stl" ;;
    placement)
            # scheme placement from constant/placement.csv: 'none' (no
            # file), 'header' (a wrong header), 'overlap' (two spheres
            # 2 mm into each other), 'outside' (a centre beyond the wall),
            # 'shape' (a cylinder in a sphere run), 'quaternion' (not of
            # unit length), 'count' (3 pellets, number 20), 'above' (a
            # sphere through the top of the container)
            foamDictionary "$dict" -entry loading -set \
                '{ scheme placement; file "constant/placement.csv"; }' \
                >/dev/null 2>&1
            [ "$2" = count ] \
                || foamDictionary "$dict" -entry pellets/number -remove >/dev/null 2>&1
            mkdir -p "$tmp/case/constant"
            csv="$tmp/case/constant/placement.csv"
            {
                [ "$2" = header ] && echo 'id,x,y,z,qw,qx,qy,qz' \
                    || echo 'id,shape,x,y,z,qw,qx,qy,qz'
                echo '0,sphere,0,0,0.006,1,0,0,0'
                case "$2" in
                    overlap)    echo '1,sphere,0.001,0,0.0141,1,0,0,0' ;;
                    outside)    echo '1,sphere,0.021,0,0.02,1,0,0,0' ;;
                    shape)      echo '1,cylinder,0,0,0.02,1,0,0,0' ;;
                    quaternion) echo '1,sphere,0,0,0.02,1,0.5,0,0' ;;
                    above)      echo '1,sphere,0,0,0.097,1,0,0,0' ;;
                    *)          echo '1,sphere,0,0,0.02,1,0,0,0' ;;
                esac
                echo '2,sphere,0.012,0,0.02,1,0,0,0'
            } > "$csv"
            [ "$2" = none ] && rm "$csv" ;;
    *)      echo "unknown action '$1'"; exit 2 ;;
esac

before="$(cd "$tmp" && find . | sort)"
rbdPackBed -case "$caseArg" > "$tmp/log" 2>&1
status=$?
after="$(cd "$tmp" && find . -not -name log | sort)"

fail=0
if [ $status -eq 0 ]
then
    echo "FAIL: exit status 0"; fail=1
fi
if ! grep -Pzq -- "$expect" "$tmp/log"
then
    echo "FAIL: log does not match: $expect"; fail=1
fi
if [ "$1" != nocase ] && [ "$1" != nodict ] && [ "$1" != file ] \
    && [ "$1" != dir ] \
    && ! grep -q "packingDict" "$tmp/log"
then
    echo "FAIL: the error does not name packingDict"; fail=1
fi
if grep -Eq "Segmentation|Aborted|stack trace|^#[0-9]+ |printStack|terminate called" "$tmp/log"
then
    echo "FAIL: crash or stack trace"; fail=1
fi
if [ "$before" != "$after" ]
then
    echo "FAIL: files were written:"; diff <(echo "$before") <(echo "$after"); fail=1
fi
echo "---- rbdPackBed log ($name, exit $status) ----"
cat "$tmp/log"
exit $fail
