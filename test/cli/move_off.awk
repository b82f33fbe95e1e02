# Moves the points of an OFF file by x -> 2 Rz(90 degrees) x + (1, 2, 3): (x, y, z) becomes
# (1 - 2y, 2 + 2x, 3 + 2z). Faces are copied. Usage: awk -f move_off.awk in.off > out.off
BEGIN { state = 0 }
/^[ \t]*#/ || /^[ \t]*$/ { next }
state == 0 { if ($1 == "OFF" && NF == 1) next; if ($1 == "OFF") { $1 = ""; $0 = $0 }
             nv = $1; nf = $2; print "OFF"; print nv, nf, 0; state = (nv > 0) ? 1 : 2; v = 0; next }
state == 1 { printf "%.17g %.17g %.17g\n", 1 - 2 * $2, 2 + 2 * $1, 3 + 2 * $3; v++
             if (v == nv) state = 2; next }
state == 2 { print }
