#!/bin/sh
# gicache.sh: the irradiance cache's error against time (`make trade-cache`,
# part of `make trade`).
#
# On scenes/room.txt (the course format's closed room, with one bounce and
# with three), scenes/indirect.txt and scenes/cache-hard.txt (a thin wall,
# a narrow gap, small bright balls), each at 200 x 200, it renders a
# converged reference (uniform, GICACHE_REF samples a pixel, 64 rays each),
# then uniform sampling (-s N --gi 16), --noise and --gi-cache at several
# accuracies E (-s 16, 2048 rays a record), timing each (median of
# GICACHE_RUNS, default 3, the whole command) and measuring the 8-bit
# picture against the reference: its RMSE and the error its worst 1% of
# pixels pass (raytrace-diff's). For each scene, the cache's default (E
# 0.3) against uniform sampling at the same RMSE: uniform's time there
# read off its curve (log-log between the two points around it); and the
# floor under the cache's RMSE: -s 16 with its indirect light near exact
# (uniform, --gi GICACHE_FLOOR_RAYS, default 512, at every sample; not
# timed), the error the camera's 16 samples make whatever the cache does.
# Writes docs/gicache.md and its plot docs/gicache.svg.
#
# Usage: sh tests/bench/gicache.sh RAYTRACE RAYTRACE-DIFF [OUT.md]
# With GICACHE_PAGE_ONLY=1, writes the page and plot again from the last
# run's measurements (build/gicache) without measuring the times (the
# floors it measures when the last run left none). With
# GICACHE_KEEP_REFS=1, measures again against the references the last run
# left there (uniform renders: a change to the cache alone leaves them as
# they were), rendering only those missing.

RT=$1
DIFF=$2
OUT=${3:-docs/gicache.md}
RUNS=${GICACHE_RUNS:-3}
REF=${GICACHE_REF:-512}
FLOOR_RAYS=${GICACHE_FLOOR_RAYS:-512}
SCENES="room:1 room:3 indirect:1 cache-hard:1" # scene:bounces
DIR=build/gicache
mkdir -p "$DIR" || exit 2
. tests/lib.sh


# errors REF NAME: "RMSE WORST" of $DIR/NAME.ppm against the clamped
# reference: the RMS error and the error the worst 1% of pixels pass.
errors() {
    "$DIFF" --clamp "$DIR/$1.pfm" "$DIR/$2.ppm" 2>&1 | awk '
        /^mean error:/ { sub(/.*RMS error: /, ""); sub(/,.*/, ""); rmse = $0 }
        /^worst 1% of pixels:/ { sub(/.*error over (at least )?/, ""); worst = $1 }
        END { print rmse, worst }'
}

if [ "${GICACHE_PAGE_ONLY:-0}" != 1 ] || [ ! -s "$DIR/rows" ]; then
    : >"$DIR/rows"
    : >"$DIR/floors"
    for run in $SCENES; do
        s=${run%:*}
        b=${run#*:}
        key="$s-b$b"
        echo "gicache: $s, $b bounce(s)" >&2
        if [ "${GICACHE_KEEP_REFS:-0}" != 1 ] || [ ! -s "$DIR/$key-ref.pfm" ]; then
            "$RT" -q --size 200x200 -s "$REF" --gi 64 --gi-bounces "$b" --format pfm \
                "scenes/$s.txt" "$DIR/$key-ref.pfm" || exit 1
        fi
        while read -r opts; do
            # shellcheck disable=SC2086
            t=$(time_renders "$key-x" --size 200x200 --gi-bounces "$b" $opts "scenes/$s.txt") || exit 1
            rays=$(sed -n 's/^raytrace: rays: .* \([0-9]*\) in all$/\1/p' "$DIR/$key-x.log")
            set -- $(errors "$key-ref" "$key-x")
            printf '| %s | %s | `%s` | %.2f s | %s | %s | %s |\n' "$s" "$b" "$opts" "$t" "$1" "$2" \
                "${rays:-—}" >>"$DIR/rows"
        done <<LIST
-s 8 --gi 16
-s 16 --gi 16
-s 32 --gi 16
-s 64 --gi 16
--noise 2 --gi 8
-s 16 --gi 2048 --gi-cache --gi-cache-error 0.5
-s 16 --gi 2048 --gi-cache --gi-cache-error 0.3
-s 16 --gi 2048 --gi-cache --gi-cache-error 0.2
LIST
    done
fi

# Pixel by pixel: at -s 1 the camera's rays are the reference's, so each
# pixel's gathered light meets converged uniform gathering's (PIX_REF rays
# at every pixel, PIX_SIZE square): the cache at each accuracy E, and
# uniform gathering with a record's rays at every pixel as the yardstick.
# A row: "SCENE | BOUNCES | OPTIONS | TIME | RECORDS | RMSE | OVER 5 | WORST".
PIX_SIZE=${GICACHE_PIXEL_SIZE:-120}
PIX_REF=${GICACHE_PIXEL_REF:-4096}
PIX_SCENES="room:1 room:2 indirect:1 cache-hard:1"
PIX_ERRORS="0.5 0.3 0.2 0.1 0.05"

# pixel_errors REF NAME: "RMSE OVER WORST" of $DIR/NAME.ppm against the
# clamped reference: the RMS error, the share of pixels more than 5 levels
# off (%) and the largest error of a channel.
pixel_errors() {
    "$DIFF" --clamp -t 5 "$DIR/$1.pfm" "$DIR/$2.ppm" 2>&1 | awk '
        /^max error:/ { worst = $3 }
        /^mean error:/ { sub(/.*RMS error: /, ""); sub(/,.*/, ""); rmse = $0 }
        /^over tolerance 5:/ { over = $8; gsub(/[(%),]/, "", over) }
        END { print rmse, over, worst }'
}

if [ "${GICACHE_PAGE_ONLY:-0}" != 1 ] || [ ! -s "$DIR/pixels" ]; then
    : >"$DIR/pixels"
    : >"$DIR/pixels-plot"
    for run in $PIX_SCENES; do
        s=${run%:*}
        b=${run#*:}
        key="$s-b$b-px"
        size="${PIX_SIZE}x$PIX_SIZE"
        echo "gicache: pixel by pixel, $s, $b bounce(s)" >&2
        if [ "${GICACHE_KEEP_REFS:-0}" != 1 ] || [ ! -s "$DIR/$key-ref.pfm" ]; then
            "$RT" -q --size "$size" --gi "$PIX_REF" --gi-bounces "$b" --format pfm \
                "scenes/$s.txt" "$DIR/$key-ref.pfm" || exit 1
        fi
        for e in uniform $PIX_ERRORS; do
            if [ "$e" = uniform ]; then
                opts="--gi 2048"
            else
                opts="--gi 2048 --gi-cache --gi-cache-error $e"
            fi
            # shellcheck disable=SC2086
            t=$(RUNS=1 && time_renders "$key-x" --size "$size" --gi-bounces "$b" $opts \
                "scenes/$s.txt") || exit 1
            records=$(sed -n 's/^raytrace: irradiance cache: error [0-9.]*, \([0-9]*\) records.*/\1/p' \
                "$DIR/$key-x.log")
            set -- $(pixel_errors "$key-ref" "$key-x")
            printf '| %s | %s | `%s` | %.2f s | %s | %s | %s%% | %s |\n' "$s" "$b" "$opts" "$t" \
                "${records:-—}" "$1" "$2" "$3" >>"$DIR/pixels"
            [ "$e" = uniform ] || echo "$s-b$b $e $2 $3" >>"$DIR/pixels-plot"
            # The picture of the error, where it is worst and where it is least.
            if [ "$key" = room-b1-px ] && { [ "$e" = 0.3 ] || [ "$e" = 0.05 ]; }; then
                "$DIFF" --clamp -t 5 -d "$(dirname "$OUT")/gicache-error-$e.png" \
                    "$DIR/$key-ref.pfm" "$DIR/$key-x.ppm" >/dev/null 2>&1
            fi
        done
    done
fi

# The floors: "SCENE | BOUNCES | RMSE" of -s 16 with the indirect light near
# exact, against the same references.
if [ ! -s "$DIR/floors" ]; then
    for run in $SCENES; do
        s=${run%:*}
        b=${run#*:}
        echo "gicache: the -s 16 floor, $s, $b bounce(s)" >&2
        "$RT" -q --size 200x200 -s 16 --gi "$FLOOR_RAYS" --gi-bounces "$b" "scenes/$s.txt" \
            "$DIR/$s-b$b-floor.ppm" || exit 1
        set -- $(errors "$s-b$b-ref" "$s-b$b-floor")
        echo "$s | $b | $1" >>"$DIR/floors"
    done
fi

# From the rows: the plot's points (a series a scene and bounces and kind:
# uniform, noise, cache), and for each scene the cache's default (E 0.3)
# against uniform's time at its RMSE, on uniform's curve.
awk -F'|' '
    function trim(v) { gsub(/^ +| +$|`/, "", v); return v }
    FNR == NR { floor[trim($1) " | " trim($2)] = trim($3) + 0; next }
    {
        scene = trim($2); b = trim($3); opts = trim($4); t = trim($5) + 0; e = trim($6) + 0
        r = trim($8) + 0
        kind = opts ~ /--gi-cache/ ? "cache" : opts ~ /--noise/ ? "noise" : "uniform"
        print scene "-b" b "-" kind, t, e > plot
        key = scene " | " b
        if (!(key in seen)) { seen[key] = 1; order[++keys] = key }
        if (kind == "uniform") { n[key]++; ut[key, n[key]] = t; ue[key, n[key]] = e; ur[key, n[key]] = r }
        if (opts ~ /--gi-cache-error 0.3$/) { ct[key] = t; ce[key] = e; cr[key] = r }
    }
    END {
        for (k = 1; k <= keys; k++) {
            key = order[k]; m = n[key]; c = ce[key]; at = 0; rat = 0
            f0 = floor[key]
            own = c > f0 ? sprintf("%.3f", sqrt(c * c - f0 * f0)) : "none (below the floor)"
            for (i = 1; i < m; i++)
                if (ue[key, i] >= c && ue[key, i + 1] <= c) {
                    f = (log(c) - log(ue[key, i])) / (log(ue[key, i + 1]) - log(ue[key, i]))
                    at = exp(log(ut[key, i]) + f * (log(ut[key, i + 1]) - log(ut[key, i])))
                    if (ur[key, i] > 0 && ur[key, i + 1] > 0)
                        rat = exp(log(ur[key, i]) + f * (log(ur[key, i + 1]) - log(ur[key, i])))
                }
            rays = rat > 0 && cr[key] > 0 ? sprintf("%.1f M | %.1f M | %.2f", cr[key] / 1e6, rat / 1e6, cr[key] / rat) : "— | — | —"
            if (at > 0)
                printf "| %s | %.3f | %.3f | %s | %.2f s | %.2f s | %.2f | %s |\n", key, c, f0, own, ct[key], at, ct[key] / at, rays
            else if (c < ue[key, m])
                printf "| %s | %.3f | %.3f | %s | %.2f s | over %.2f s (-s 64: RMSE %.3f) | under %.2f | %s |\n", key, c, f0, own, ct[key], ut[key, m], ue[key, m], ct[key] / ut[key, m], rays
            else
                printf "| %s | %.3f | %.3f | %s | %.2f s | under %.2f s (-s 8: RMSE %.3f) | over %.2f | %s |\n", key, c, f0, own, ct[key], ut[key, 1], ue[key, 1], ct[key] / ut[key, 1], rays
        }
    }' plot="$DIR/plot" "$DIR/floors" "$DIR/rows" >"$DIR/ratios"
awk '{ print $1, $2, $3 }' "$DIR/pixels-plot" | awk -v title="Pixels more than 5 levels off at -s 1 ($PIX_SIZE x $PIX_SIZE)" \
    -v xlabel="--gi-cache-error E" -v ylabel="share of pixels over 5 levels, %" -v logx=1 \
    -f tests/bench/plot.awk >"$(dirname "$OUT")/gicache-over.svg"
awk '{ print $1, $2, $4 }' "$DIR/pixels-plot" | awk -v title="The worst pixel at -s 1 ($PIX_SIZE x $PIX_SIZE)" \
    -v xlabel="--gi-cache-error E" -v ylabel="largest error of a channel, levels" -v logx=1 \
    -f tests/bench/plot.awk >"$(dirname "$OUT")/gicache-worst.svg"
# What E buys, scene by scene: the default against the finest.
awk -F'|' '
    function trim(v) { gsub(/^ +| +$|`/, "", v); return v }
    {
        key = trim($2) ", " trim($3) " bounce" (trim($3) > 1 ? "s" : ""); o = trim($4)
        if (!(key in seen)) { seen[key] = 1; order[++n] = key }
        if (o ~ /error 0.3$/) { t0[key] = trim($5); r0[key] = trim($6); s0[key] = trim($8); w0[key] = trim($9) }
        if (o ~ /error 0.05$/) { t1[key] = trim($5); r1[key] = trim($6); s1[key] = trim($8); w1[key] = trim($9) }
        if (o !~ /cache/) { su[key] = trim($8); wu[key] = trim($9) }
    }
    END {
        for (k = 1; k <= n; k++) {
            key = order[k]
            printf "- %s: from E 0.3 to 0.05, %s to %s records and %s to %s; pixels over 5 levels %s to %s, the worst %.1f to %.1f levels (uniform gathering with a record'"'"'s rays at every pixel: %s, %.1f).\n", key, r0[key], r1[key], t0[key], t1[key], s0[key], s1[key], w0[key], w1[key], su[key], wu[key]
        }
    }' "$DIR/pixels" >"$DIR/buys"
awk -v title="Irradiance cache against uniform sampling and --noise (200 x 200)" \
    -v xlabel="render time, s" -v ylabel="RMSE against the converged render, levels" -v logx=1 -v logy=1 \
    -f tests/bench/plot.awk "$DIR/plot" >"$(dirname "$OUT")/gicache.svg"
{
    echo "# The irradiance cache: error against time"
    echo
    echo "Written by \`make trade-cache\` (tests/bench/gicache.sh) on $(uname -m), $(nproc) threads,"
    echo "$(date -u +%Y-%m-%d). Each scene at 200 × 200 against a uniform render of $REF"
    echo "samples a pixel and 64 rays (with the same bounces); time: the median of"
    echo "$RUNS runs of the whole command, every row measured in this one run. RMSE:"
    echo "the 8-bit picture against the reference's colours clamped to 0..255, in"
    echo "levels; worst 1%: the error that 1% of the pixels pass (each pixel's the"
    echo "RMS of its channels), as raytrace-diff prints it."
    echo
    echo "The cache's default (\`-s 16 --gi-cache\`: 2048 rays a record, E 0.3)"
    echo "against uniform sampling at the same RMSE (uniform's time read off its"
    echo "curve, log-log between the two -s around it). The floor: the RMSE of"
    echo "-s 16 with its indirect light near exact (uniform, --gi $FLOOR_RAYS at every"
    echo "sample), what the camera's 16 samples (against the reference's $REF) and"
    echo "the 8-bit rounding leave whatever the cache does; the cache's own error:"
    echo "the square root of its RMSE squared less the floor's. Rays: every ray the"
    echo "whole command casts (-v's count: primary, shadow and gathering rays,"
    echo "the cache's pre-pass included), the same on every run and machine;"
    echo "uniform's at the cache's RMSE read off its curve as its time is. Where"
    echo "a ray costs the cache what it costs uniform sampling, the time ratio is"
    echo "the rays ratio: the cache's rays are then what the ratio can gain on."
    echo
    echo "| scene | bounces | cache's RMSE | -s 16's floor | cache's own error | cache's time | uniform's time at that RMSE | ratio | cache's rays | uniform's rays at that RMSE | rays ratio |"
    echo "|-------|---------|--------------|---------------|-------------------|--------------|-----------------------------|-------|--------------|-----------------------------|------------|"
    cat "$DIR/ratios"
    echo
    echo "The floor is most of the error at -s 16: where it is near 1 level no"
    echo "render at -s 16, cached or not, gets within 1 level RMSE, and elsewhere"
    echo "the cache may add only what is left, which takes its default's 2048 rays"
    echo "a record. (The floors are measured against the same references, after"
    echo "the timed rows when the page is written again.)"
    echo
    echo "![error against time](gicache.svg)"
    echo
    echo "| scene | bounces | options | time | RMSE | worst 1% | rays |"
    echo "|-------|---------|---------|------|------|----------|------|"
    cat "$DIR/rows"
    echo
    echo "## Pixel by pixel"
    echo
    echo "At one sample a pixel the camera's rays are the reference's, so each"
    echo "pixel's gathered light is held to converged uniform gathering's: each"
    echo "scene at $PIX_SIZE × $PIX_SIZE, \`-s 1\`, against a uniform render of $PIX_REF rays at every"
    echo "pixel (the same bounces), its colours clamped. Over 5: the share of the"
    echo "pixels more than 5 levels off (raytrace-diff's, a pixel's error its"
    echo "largest channel's); worst: the largest error of a channel. Time: one"
    echo "run of the whole command. The first row of each scene is uniform"
    echo "gathering with a record's 2048 rays at every pixel: what the cache's"
    echo "records are themselves worth."
    echo
    echo "What E buys:"
    echo
    cat "$DIR/buys"
    echo
    echo "![pixels over 5 levels against E](gicache-over.svg)"
    echo
    echo "![the worst pixel against E](gicache-worst.svg)"
    echo
    echo "Where the room's pixels are more than 5 levels off (in red, over the"
    echo "darkened reference), at E 0.3 and at E 0.05:"
    echo
    echo "![the room's error at E 0.3](gicache-error-0.3.png) ![the room's error at E 0.05](gicache-error-0.05.png)"
    echo
    echo "| scene | bounces | options | time | records | RMSE | over 5 | worst |"
    echo "|-------|---------|---------|------|---------|------|--------|-------|"
    cat "$DIR/pixels"
} >"$OUT"
echo "gicache: wrote $OUT" >&2
