# Sourced by scripts/run-tests.sh and scripts/run-sanitizer-tests.sh. `step NAME COMMAND...` runs
# COMMAND and prints how long it took: wall-clock seconds, and CPU seconds (user + system) of every
# process it ran, which other load on the machine changes less. `steps_summary` prints every step again,
# so that each CI run shows where its time went (docs/reliability.md, "CI time").
steps_file=$(mktemp)
trap 'rm -f "$steps_file"' EXIT
steps_done=()

# Sets steps_cpu to the CPU seconds of the processes this shell has run so far (bash's `times`, run in
# this shell: in a command substitution it would count the subshell's children only).
steps_cpu_now() {
    times >"$steps_file"
    steps_cpu=$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/)
                                printf "%.2f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$steps_file")
}

step() {
    local name=$1 start=$EPOCHREALTIME cpu_start line
    shift
    steps_cpu_now
    cpu_start=$steps_cpu
    "$@"
    steps_cpu_now
    line=$(awk -v n="$name" -v t0="$start" -v t1="$EPOCHREALTIME" -v c0="$cpu_start" -v c1="$steps_cpu" \
        'BEGIN { printf "%-34s %5.0f s wall %6.0f s CPU", n, t1 - t0, c1 - c0 }')
    steps_done+=("$line")
    echo "step: $line"
}

steps_summary() {  # TITLE
    echo "$1 ($(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)):"
    printf '  %s\n' "${steps_done[@]}"
    printf '  %-34s %5d s wall\n' "total" "$SECONDS"
}
