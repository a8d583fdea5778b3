# profile.awk - reads a Callgrind file written with --compress-strings=no
# and --compress-pos=no (one event, Ir) and prints where a frame's
# instructions go, by stage of mote's pipeline, for `make profile`.
#
# Each function of mote (one defined in a file under src/) is put in a
# stage by its name (stage() below); a function outside mote (memcpy,
# memset) counts in the stage of the mote function that called it. Per
# unit: instructions a set-up call (setup), a fill call (fills: one
# triangle in one tile, with its edge walk), and a frame (calls of
# mote_begin).
#
# Variables: scene (a title for the table).

function stage(f) {
    if (!(f in in_mote)) return ""
    if (f ~ /^mote__clear|^mote__fill_rows/) return "clear"
    if (f ~ /^mote__(fill_|vfill_|walk_|raster_|warm_tile)/) return "fills"
    if (f ~ /^mote__setup/) return "setup"
    if (f ~ /^mote__(transform|finish|light|prepare_vertices|vertex|tint|shade|snap)/) return "vertex"
    if (f ~ /^mote_/) return "other"
    return ""
}

# the file a function is defined in: fl= before fn=, cfi= or cfl= before
# cfn= (the caller's file when neither is given)
/^fl=/ { file = substr($0, 4); next }
/^cf[il]=/ { cfile = substr($0, 5); next }
/^fn=/ {
    fn = substr($0, 4)
    if (file ~ /\/src\//) in_mote[fn] = 1
    next
}
/^cfn=/ {
    cfn = substr($0, 5)
    if ((cfile != "" ? cfile : file) ~ /\/src\//) in_mote[cfn] = 1
    cfile = ""
    next
}
/^calls=/ { split(substr($0, 7), a, " "); ncalls = a[1]; in_call = 1; next }
/^[0-9]+ [0-9]+$/ {
    if (in_call) {
        calls[fn, cfn] += ncalls
        cost[fn, cfn] += $2
        in_call = 0
    } else {
        self[fn] += $2
    }
    next
}

END {
    total = 0
    for (f in self) {
        total += self[f]
        s = stage(f)
        if (s != "") sum[s] += self[f]
    }
    # calls out of mote (memcpy, memset): to the caller's stage
    for (k in cost) {
        split(k, p, SUBSEP)
        if (stage(p[2]) == "" && stage(p[1]) != "") sum[stage(p[1])] += cost[k]
    }
    frames = fills = setups = 0
    for (k in calls) {
        split(k, p, SUBSEP)
        if (p[2] == "mote_begin") frames += calls[k]
        if (p[2] == "mote__setup") setups += calls[k]
        # a variant's fallback to the generic loop is not a second fill
        if (stage(p[2]) == "fills" && p[2] ~ /^mote__fill_/ && p[1] !~ /^mote__fill_/) fills += calls[k]
    }
    if (frames == 0 || total == 0) {
        print "profile: no frame was recorded (no call of mote_begin)" > "/dev/stderr"
        exit 1
    }
    printf "%s: %.1f M instructions a frame (Callgrind, %d frames)\n\n", scene, total / frames / 1e6, frames
    printf "| stage | M instructions a frame | share | per unit |\n|---|---|---|---|\n"
    n = split("fills setup vertex other clear", order, " ")
    name["fills"] = "fills (edge walks and pixel loops)"
    name["setup"] = "triangle setup"
    name["vertex"] = "vertex stage (transform, snap, lighting)"
    name["other"] = "culling, binning, triangle loop"
    name["clear"] = "clear"
    for (i = 1; i <= n; i++) {
        s = order[i]
        unit = ""
        if (s == "fills" && fills > 0)
            unit = sprintf("%.0f a fill call (%.0f fill calls a frame)", sum[s] / fills, fills / frames)
        if (s == "setup" && setups > 0)
            unit = sprintf("%.0f a triangle set up (%.0f a frame)", sum[s] / setups, setups / frames)
        printf "| %s | %.1f | %.1f%% | %s |\n", name[s], sum[s] / frames / 1e6, 100 * sum[s] / total, unit
        assigned += sum[s]
    }
    if (total - assigned > total / 1000)   # outside mote and called from outside it
        printf "| not assigned | %.1f | %.1f%% | |\n", (total - assigned) / frames / 1e6, 100 * (total - assigned) / total
}
