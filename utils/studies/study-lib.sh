# Shared by the scripts of utils/studies/ (sourced, not run): the common options, the decks of
# a study's runs (written by utils/decks/deck_writer.py and checked before any run starts),
# running them a few at a time, and drawing and checking figures.
#
# A script sets STUDY (its name, used in messages and default folders), APP (the app it runs)
# and optionally DEFAULT_RANKS and DEFAULT_JOBS, defines
#   usage            prints its --help text (common_options_help prints the shared options)
#   study_option     (optional) handles one option of its own: "$1" is the option, "$2" the
#                    next word; it sets consumed=1 or 2 (0 or unset: not its option)
# then sources this file and calls parse_options "$@". The positional arguments are then in
# the array `positional`. queue_run NAME DECK [--set "List/Key=value"]... adds a run;
# run_queued writes every queued deck to RUNS/NAME.xml and runs them, at most JOBS at a time,
# into RUNS/NAME (log RUNS/NAME.log, wall seconds in RUNS/.seconds). The figure studies
# (cell3d.sh, twocell3d.sh, tether2d.sh) use figure_study_main, which adds the modes and FIGDIR.

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
python=/usr/bin/python3   # Debian's python3 with python3-numpy, -matplotlib, -h5py
plotting="$here/utils/plotting"
deck_writer="$here/utils/decks/deck_writer.py"

build="$here/build"
runs=""
jobs=${DEFAULT_JOBS:-2}
ranks=${DEFAULT_RANKS:-1}
plot_only=0
keep_finished=0
positional=()
queued=()
failed_runs=0

common_options_help() {
  cat <<EOF
  --build DIR  the build directory with the apps (default: build)
  --runs DIR   where the runs write (default: $(default_runs_hint)); each run's deck is
               RUNS/<name>.xml, its log RUNS/<name>.log
  --jobs N     runs at the same time (default $jobs)
  --ranks N    MPI ranks per run (default $ranks; 1 runs without mpiexec)
  --keep-finished  do not run again a run that finished (its summary.json says so) from
               the same deck (RUNS/<name>.xml unchanged): a study extended by new decks
               runs only those
  --help       this text
EOF
}

default_runs_hint() { echo "out/$STUDY"; }

die() {
  echo "$STUDY: $*" >&2
  exit 1
}

parse_options() {
  while [[ $# -gt 0 ]]; do
    consumed=0
    if declare -F study_option > /dev/null; then
      study_option "$1" "${2-}"
    fi
    if [[ $consumed -gt 0 ]]; then
      [[ $consumed -le $# ]] || die "option $1 needs a value (see --help)"
      shift "$consumed"
      continue
    fi
    case "$1" in
      --build) [[ $# -ge 2 ]] || die "--build needs a value"; build="$2"; shift ;;
      --runs) [[ $# -ge 2 ]] || die "--runs needs a value"; runs="$2"; shift ;;
      --jobs) [[ $# -ge 2 ]] || die "--jobs needs a value"; jobs="$2"; shift ;;
      --ranks) [[ $# -ge 2 ]] || die "--ranks needs a value"; ranks="$2"; shift ;;
      --keep-finished) keep_finished=1 ;;
      -h|--help) usage; exit 0 ;;
      -*) die "unknown option '$1' (see --help)" ;;
      *) positional+=("$1") ;;
    esac
    shift
  done
  [[ "$jobs" =~ ^[1-9][0-9]*$ ]] || die "--jobs must be a positive integer, got '$jobs'"
  [[ "$ranks" =~ ^[1-9][0-9]*$ ]] || die "--ranks must be a positive integer, got '$ranks'"
  [[ "$build" = /* ]] || build="$PWD/$build"
  [[ -n "$runs" ]] || runs="$here/$(default_runs_hint)"
  [[ "$runs" = /* ]] || runs="$PWD/$runs"
  app_path="$build/apps/$APP/$APP"
  [[ -x "$python" ]] || die "$python is missing; run utils/install-deps.sh"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  # The plotting scripts import capsula_outputs from their folder; no __pycache__ in the sources.
  export PYTHONPATH="$plotting${PYTHONPATH:+:$PYTHONPATH}" PYTHONDONTWRITEBYTECODE=1
}

require_app() {
  [[ -x "$app_path" ]] ||
    die "no $app_path; build it first (cmake --build $build --target $APP) or pass --build DIR"
}

# queue_run NAME DECK [--set "List/Key=value"]...: adds a run of DECK (a path under the
# repository or absolute) with these changes, into RUNS/NAME.
queue_run() {
  local name="$1" deck="$2" line
  shift 2
  [[ "$deck" = /* ]] || deck="$here/$deck"
  line="$name"$'\t'"$deck"
  while [[ $# -gt 0 ]]; do
    if [[ "$1" == --set ]]; then
      line+=$'\t'"$2"
      shift 2
    else
      line+=$'\t'"$1"
      shift
    fi
  done
  queued+=("$line")
}

# run_queued: writes the queued decks (all are checked before any run starts) and runs them,
# at most $jobs at a time; failed_runs counts the runs that stopped with an error.
run_queued() {
  local line name start
  [[ ${#queued[@]} -gt 0 ]] || return 0
  require_app
  mkdir -p "$runs"
  local -A finished=()
  if [[ $keep_finished -eq 1 ]]; then
    # The runs that finished, with the checksum of the deck they ran from (compared below
    # with the deck written now).
    for line in "${queued[@]}"; do
      name=${line%%$'\t'*}
      if [[ -f "$runs/$name.xml" ]] && grep -q '"status": "finished"' "$runs/$name/summary.json" 2>/dev/null; then
        finished[$name]=$(cksum < "$runs/$name.xml")
      fi
    done
  fi
  printf '%s\n' "${queued[@]}" > "$runs/.decks.tsv"
  "$python" "$deck_writer" manifest --app "$APP" --build "$build" --runs "$runs" "$runs/.decks.tsv" > /dev/null ||
    die "the decks were not written (see the message above); nothing was run"
  rm -f "$runs/.failed"
  for line in "${queued[@]}"; do
    name=${line%%$'\t'*}
    if [[ -n "${finished[$name]-}" && "${finished[$name]}" == "$(cksum < "$runs/$name.xml")" ]]; then
      echo "  kept    $name (finished from the same deck)"
      continue
    fi
    while [[ $(jobs -rp | wc -l) -ge $jobs ]]; do
      wait -n || true
    done
    (
      start=$SECONDS
      launcher=()
      [[ $ranks -le 1 ]] || launcher=(mpiexec -n "$ranks" --oversubscribe)
      rm -rf "${runs:?}/$name"
      if "${launcher[@]}" "$app_path" "$runs/$name.xml" --output "$runs/$name" > "$runs/$name.log" 2>&1; then
        echo "  done    $name ($((SECONDS - start)) s)"
      else
        echo "  FAILED  $name ($((SECONDS - start)) s): $(grep -m1 -i "error" "$runs/$name.log" | cut -c1-160)"
        echo "$name" >> "$runs/.failed"
      fi
      echo "$name $((SECONDS - start))" >> "$runs/.seconds"
    ) &
  done
  wait
  queued=()
  if [[ -s "$runs/.failed" ]]; then
    failed_runs=$(wc -l < "$runs/.failed")
  fi
}

# seconds_of NAME: the wall seconds of the last run NAME (from RUNS/.seconds).
seconds_of() {
  awk -v n="$1" '$1 == n { s = $2 } END { print s }' "$runs/.seconds" 2>/dev/null
}

# draw SCRIPT [ARGS...]: runs a plotting script on the runs folder.
draw() {
  local script="$1"
  shift
  if ! "$python" "$plotting/$script" --out "$figures" "$@" "$runs" | sed 's/^/  /'; then
    draw_failed=1
  fi
}

# --- the figure studies (cell3d.sh, twocell3d.sh, tether2d.sh) -------------------------------
# The script defines study_runs (queue_run for each deck of $mode), study_figures (draw for
# each plotting script) and the array EXPECTED (the PNG files its figures must produce).

mode=reduced
check=0
figures=""

figure_study_usage() {
  cat <<EOF
Usage: utils/studies/$STUDY.sh [--quick | --full] [options] FIGDIR

Runs the $STUDY study decks and draws the thesis's figures of it as PNG files in FIGDIR.

  --quick      tiny meshes and short times: every figure in about a minute on 2 cores
               (what the ctest test figures_${STUDY}_quick runs); the pictures show the
               code works, not the physics
  (default)    reduced: coarser meshes and shorter times than the thesis, minutes of CPU
               (what made docs/figures/)
  --full       the study decks as they stand (thesis resolution): hours to days
  --plot-only  draw from the runs already in the runs folder
  --check      afterwards check that each expected figure exists and is not blank
               (utils/plotting/check_figures.py)
$(common_options_help; if declare -F study_options_help > /dev/null; then study_options_help; fi)

Exit status: 0 when every run finished and every figure was drawn (and passed --check);
1 otherwise (the log of each run is RUNS/<name>.log).
EOF
}

figure_study_option() {
  case "$1" in
    --quick) mode=quick; consumed=1 ;;
    --full) mode=full; consumed=1 ;;
    --plot-only) plot_only=1; consumed=1 ;;
    --check) check=1; consumed=1 ;;
  esac
}

figure_study_main() {
  usage() { figure_study_usage; }
  study_option() { figure_study_option "$@"; }
  default_runs_hint() { if [[ $mode == reduced ]]; then echo "out/study-$STUDY"; else echo "out/study-$STUDY-$mode"; fi; }
  parse_options "$@"
  [[ ${#positional[@]} -eq 1 ]] || die "give one FIGDIR (see --help), got ${#positional[@]}"
  figures=${positional[0]}
  [[ "$figures" = /* ]] || figures="$PWD/$figures"
  mkdir -p "$runs" "$figures"
  local start=$SECONDS status=0
  if [[ $plot_only -eq 0 ]]; then
    require_app
    echo "== $STUDY study ($mode): runs in $runs, $jobs at a time, $ranks rank(s) each"
    study_runs
    run_queued
    if [[ $failed_runs -gt 0 ]]; then
      echo "== $failed_runs run(s) stopped early (see RUNS/<name>.log; docs/figures.md):"
      sed 's/^/  /' "$runs/.failed"
      status=1
    fi
    echo "== runs took $((SECONDS - start)) s"
  fi
  echo "== figures in $figures"
  # The study's own figures are drawn afresh (a stale one must not pass --check).
  for name in "${EXPECTED[@]}"; do rm -f "$figures/$name"; done
  draw_failed=0
  study_figures
  [[ $draw_failed -eq 0 ]] || status=1
  if [[ $check -eq 1 ]]; then
    "$python" "$plotting/check_figures.py" "$figures" "${EXPECTED[@]}" || status=1
  fi
  echo "== $STUDY study done in $((SECONDS - start)) s (exit status $status)"
  return $status
}
