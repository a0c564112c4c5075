#!/bin/sh
# quote.sh: brings the tables report.md quotes up to date from the pages
# that hold them, so that each measured figure is written once, by the
# program that measures it (make bench, make trade, ...), and the report
# only copies it. A quote is the lines between
#
#   <!-- quote PAGE "HEADING" columns N N ... -->
#   <!-- end quote -->
#
# and is replaced by the first Markdown table after the line HEADING of
# PAGE (a path from the repository root), keeping columns N ... (from 1)
# in that order. Writes the report to standard output; exits 1, naming
# the quote, when its page, heading or table is not there.
#
# Usage: sh report/quote.sh [REPORT]   (from the repository root; REPORT
# defaults to report/report.md)

report=${1:-report/report.md}
LC_ALL=C
export LC_ALL

awk '
    # The table after heading h of page p, columns cols (space-separated).
    function table(p, h, cols,    line, found, in_table, n, ncols, c, i, out, parts, k, status) {
        found = 0; in_table = 0; out = ""
        ncols = split(cols, c, " ")
        while ((status = (getline line < p)) > 0) {
            if (!found) { found = (line == h); continue }
            if (line ~ /^\|/) {
                in_table = 1
                n = split(line, parts, "|")
                out = out "|"
                for (i = 1; i <= ncols; i++) {
                    k = c[i] + 1
                    if (k >= n) { close(p); return "" }
                    out = out parts[k] "|"
                }
                out = out "\n"
            } else if (in_table) {
                break
            }
        }
        close(p)
        if (status < 0) return ""
        return out
    }
    /^<!-- quote / {
        print
        spec = $0
        sub(/^<!-- quote /, "", spec); sub(/ -->$/, "", spec)
        page = spec; sub(/ .*/, "", page)
        heading = spec; sub(/^[^"]*"/, "", heading); sub(/".*/, "", heading)
        cols = spec; sub(/.*" columns /, "", cols)
        t = table(page, heading, cols)
        if (t == "") {
            printf "quote.sh: %s:%d: no table after \"%s\" in %s with columns %s\n",
                FILENAME, FNR, heading, page, cols > "/dev/stderr"
            bad = 1
        }
        printf "%s", t
        skipping = 1
        next
    }
    /^<!-- end quote -->$/ { skipping = 0 }
    !skipping { print }
    END { exit bad }
' "$report"
