# plot.awk: a line chart as SVG, for the trade measurements (no plotting
# package needed).
#
# Input: one point a line, "SERIES X Y LABEL" (LABEL optional, written next
# to the point). Variables: title, xlabel, ylabel; logx=1 and logy=1 for
# logarithmic axes (points with a value <= 0 there are left out).
# Usage: awk -v title=T -v xlabel=X -v ylabel=Y [-v logx=1] [-v logy=1] -f plot.awk DATA

function tx(v) { return logx ? log(v) / log(10) : v }
function ty(v) { return logy ? log(v) / log(10) : v }
function px(v) { return L + (tx(v) - x0) / (x1 - x0) * (W - L - R) }
function py(v) { return H - B - (ty(v) - y0) / (y1 - y0) * (H - T - B) }
function floor(v,   f) { f = int(v); return f > v ? f - 1 : f }
function ceil(v,   c) { c = int(v); return c < v ? c + 1 : c }
function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); return s }
function tick(v, log_axis) {
    return sprintf("%.3g", log_axis ? 10 ^ v : v)
}

BEGIN { W = 660; H = 420; L = 90; R = 150; T = 50; B = 50; n = 0; ns = 0 }

NF >= 3 && (!logx || $2 > 0) && (!logy || $3 > 0) {
    n++
    s[n] = $1; x[n] = $2; y[n] = $3
    lab[n] = NF >= 4 ? $4 : ""
    if (!($1 in seen)) { seen[$1] = 1; ns++; order[ns] = $1 }
    if (n == 1 || tx($2) < x0) x0 = tx($2)
    if (n == 1 || tx($2) > x1) x1 = tx($2)
    if (n == 1 || ty($3) < y0) y0 = ty($3)
    if (n == 1 || ty($3) > y1) y1 = ty($3)
}

END {
    # Room on the right for the longest series name (about 7 px a letter).
    for (k = 1; k <= ns; k++)
        if (36 + 7 * length(order[k]) > R) { W += 36 + 7 * length(order[k]) - R; R = 36 + 7 * length(order[k]) }
    if (n == 0) { x0 = 0; x1 = 1; y0 = 0; y1 = 1 }
    if (x1 == x0) { x0 -= 0.5; x1 += 0.5 }
    if (y1 == y0) { y0 -= 0.5; y1 += 0.5 }
    pad = (y1 - y0) * 0.05; y0 -= pad; y1 += pad
    if (!logy && y0 < 0 && y0 > -pad * 2) y0 = 0
    # Log axes spanning a decade or more are cut at whole decades.
    if (logx && x1 - x0 >= 1) { x0 = floor(x0); x1 = ceil(x1) }
    if (logy && y1 - y0 >= 1) { y0 = floor(y0); y1 = ceil(y1) }
    # Ten colours; past ten series they come again, dashed.
    split("#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #17becf #8c564b #e377c2 #7f7f7f #bcbd22", colours, " ")
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H
    printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H
    printf "<text x=\"%d\" y=\"24\" font-size=\"15\">%s</text>\n", L, esc(title)
    # Axes and ticks: 5 divisions each way.
    printf "<g stroke=\"#888\">\n<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\"/>\n", L, H - B, W - R, H - B
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\"/>\n</g>\n", L, T, L, H - B
    # Ticks: every decade of a log axis that spans some, else 5 steps.
    nx = logx && x1 - x0 >= 1 ? x1 - x0 : 5
    ny = logy && y1 - y0 >= 1 ? y1 - y0 : 5
    if (nx > 12) nx = 12
    if (ny > 12) ny = 12
    for (i = 0; i <= nx; i++) {
        vx = x0 + (x1 - x0) * i / nx; gx = L + (W - L - R) * i / nx
        printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#eee\"/>\n", gx, T, gx, H - B
        printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>\n", gx, H - B + 16, tick(vx, logx)
    }
    for (i = 0; i <= ny; i++) {
        vy = y0 + (y1 - y0) * i / ny; gy = H - B - (H - T - B) * i / ny
        printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#eee\"/>\n", L, gy, W - R, gy
        printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n", L - 6, gy + 4, tick(vy, logy)
    }
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">%s%s</text>\n", (L + W - R) / 2, H - 12, esc(xlabel), logx ? " (log scale)" : ""
    printf "<text x=\"16\" y=\"%d\" text-anchor=\"middle\" transform=\"rotate(-90 16 %d)\">%s%s</text>\n", (T + H - B) / 2, (T + H - B) / 2, esc(ylabel), logy ? " (log scale)" : ""
    for (k = 1; k <= ns; k++) {
        c = colours[(k - 1) % 10 + 1]
        dash = k > 10 ? " stroke-dasharray=\"6 3\"" : ""
        pts = ""
        for (i = 1; i <= n; i++)
            if (s[i] == order[k])
                pts = pts sprintf("%.1f,%.1f ", px(x[i]), py(y[i]))
        printf "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\"%s points=\"%s\"/>\n", c, dash, pts
        for (i = 1; i <= n; i++)
            if (s[i] == order[k]) {
                printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n", px(x[i]), py(y[i]), c
                if (lab[i] != "")
                    printf "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" fill=\"%s\">%s</text>\n", px(x[i]) + 5, py(y[i]) - 5, c, esc(lab[i])
            }
        if (dash != "")
            printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\" stroke-width=\"3\"%s/>\n", W - R + 8, T + 18 * (k - 1) + 6, W - R + 26, T + 18 * (k - 1) + 6, c, dash
        else
            printf "<rect x=\"%d\" y=\"%d\" width=\"12\" height=\"12\" fill=\"%s\"/>\n", W - R + 12, T + 18 * (k - 1), c
        printf "<text x=\"%d\" y=\"%d\">%s</text>\n", W - R + 30, T + 18 * (k - 1) + 11, esc(order[k])
    }
    print "</svg>"
}
