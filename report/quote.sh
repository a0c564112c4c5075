#!/bin/sh
# quote.sh: brings the tables and figures report.md quotes up to date from
# the pages that hold them, so that each measured figure is written once,
# by the program that measures it (make bench, make trade, ...), and the
# report only copies it. A quoted table is the lines between
#
#   <!-- quote PAGE "HEADING" columns N N ... -->
#   <!-- end quote -->
#
# replaced by the first Markdown table after the line HEADING of PAGE (a
# path from the repository root), keeping columns N ... (from 1) in that
# order. A quoted figure, within a line, is the text between
#
#   <!-- cell PAGE "HEADING" "ROW" N [FORMAT] -->...<!-- /cell -->
#
# replaced by column N of the row of that table whose first columns read
# ROW ("GI | 1024" for two), through the printf FORMAT when one is given
# ("%.1f": the number rounded), or its part in brackets for FORMAT "()". Writes the report to standard output;
# exits 1, naming the quote, when its page, heading, table, row or column
# is not there.
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
    # Column col of the row of the table after heading h of page p whose
    # first columns read key ("" when there is none).
    function cell(p, h, key, col,    line, found, in_table, parts, n, status, out) {
        found = 0; in_table = 0; out = ""
        while ((status = (getline line < p)) > 0) {
            if (!found) { found = (line == h); continue }
            if (line ~ /^\|/) {
                in_table = 1
                if (index(line, "| " key " |") == 1) {
                    n = split(line, parts, "|")
                    if (col + 1 < n) { out = parts[col + 1]; gsub(/^ +| +$/, "", out) }
                    break
                }
            } else if (in_table) {
                break
            }
        }
        close(p)
        return out
    }
    /<!-- cell / {
        rest = $0; line = ""
        while ((at = index(rest, "<!-- cell ")) > 0) {
            line = line substr(rest, 1, at - 1)
            rest = substr(rest, at)
            close_at = index(rest, " -->")
            spec = substr(rest, 11, close_at - 11)
            rest = substr(rest, close_at + 4)
            end_at = index(rest, "<!-- /cell -->")
            if (end_at == 0) {
                printf "quote.sh: %s:%d: a cell quote without its end\n", FILENAME, FNR > "/dev/stderr"
                bad = 1; break
            }
            rest = substr(rest, end_at + 14)
            page = spec; sub(/ .*/, "", page)
            split(spec, q, "\"")
            heading = q[2]; key = q[4]; tail_spec = q[5]; sub(/^ +/, "", tail_spec)
            split(tail_spec, ts, " ")
            v = cell(page, heading, key, ts[1] + 0)
            if (v == "") {
                printf "quote.sh: %s:%d: no row \"%s\" column %s in the table after \"%s\" in %s\n",
                    FILENAME, FNR, key, ts[1], heading, page > "/dev/stderr"
                bad = 1
            }
            if (ts[2] == "()") { sub(/^[^(]*\(/, "", v); sub(/\).*$/, "", v) }
            else if (ts[2] != "") v = sprintf(ts[2], v + 0)
            line = line "<!-- cell " spec " -->" v "<!-- /cell -->"
        }
        $0 = line rest
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
