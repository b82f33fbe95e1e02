# Rewrites a triangle OFF file as an unindexed soup: every face gets its own three points.
# Usage: awk -f unindex_off.awk in.off > out.off
BEGIN { state = 0 }
/^[ \t]*#/ || /^[ \t]*$/ { next }
state == 0 { if ($1 == "OFF" && NF == 1) next; if ($1 == "OFF") { $1 = "" ; $0 = $0 }
             nv = $1; nf = $2; state = 1; v = 0; next }
state == 1 { x[v] = $1; y[v] = $2; z[v] = $3; v++; if (v == nv) { state = 2; f = 0 }; next }
state == 2 { a[f] = $2; b[f] = $3; c[f] = $4; f++; if (f == nf) state = 3; next }
END {
  print "OFF"; print 3 * nf, nf, 0
  for (i = 0; i < nf; i++) {
    print x[a[i]], y[a[i]], z[a[i]]; print x[b[i]], y[b[i]], z[b[i]]; print x[c[i]], y[c[i]], z[c[i]]
  }
  for (i = 0; i < nf; i++) print 3, 3 * i, 3 * i + 1, 3 * i + 2
}
