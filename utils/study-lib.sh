# Shared by utils/study-*.sh (sourced, not run): the command line, running decks, drawing
# and checking figures. A study script sets STUDY (its name) and APP, defines
# study_runs (calls run_deck for each deck) and study_figures (calls draw for each
# plotting script) and the array EXPECTED (the PNG files its figures must produce), then
# calls study_main "$@".

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
python=/usr/bin/python3   # Debian's python3 with python3-numpy, -matplotlib, -h5py
plotting="$here/utils/plotting"

usage() {
  cat <<EOF
Usage: utils/study-$STUDY.sh [--quick | --full] [--build DIR] [--runs DIR] [--jobs N] [--ranks N]
                            [--plot-only] [--check] FIGDIR

Runs the $STUDY study decks and draws the thesis's figures of it as PNG files in FIGDIR.

  --quick      tiny meshes and short times: every figure in about a minute on 2 cores
               (what the ctest test figures_${STUDY}_quick runs); the pictures show the
               code works, not the physics
  (default)    reduced: coarser meshes and shorter times than the thesis, minutes of CPU
               (what made docs/figures/)
  --full       the study decks as they stand (thesis resolution): hours to days
  --build DIR  the build directory with the apps (default: build)
  --runs DIR   where the runs write (default: out/study-$STUDY[-quick|-full]); a run is
               redone unless --plot-only
  --jobs N     decks run at the same time (default 2)
  --ranks N    MPI ranks per run (default: $DEFAULT_RANKS; 1 runs without mpiexec)
  --plot-only  draw from the runs already in the runs folder
  --check      afterwards check that each expected figure exists and is not blank
               (utils/plotting/check_figures.py)

Exit status: 0 when every run finished and every figure was drawn (and passed --check);
1 otherwise (the log of each run is RUNS/<name>.log).
EOF
}

mode=reduced
build="$here/build"
runs=""
jobs=2
ranks=${DEFAULT_RANKS:-1}
plot_only=0
check=0
figures=""
failed_runs=()

parse_arguments() {
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --quick) mode=quick ;;
      --full) mode=full ;;
      --build) build="$2"; shift ;;
      --runs) runs="$2"; shift ;;
      --jobs) jobs="$2"; shift ;;
      --ranks) ranks="$2"; shift ;;
      --plot-only) plot_only=1 ;;
      --check) check=1 ;;
      -h|--help) usage; exit 0 ;;
      -*) echo "study-$STUDY: unknown option '$1' (see --help)" >&2; exit 1 ;;
      *) [[ -z "$figures" ]] || { echo "study-$STUDY: one FIGDIR only, got '$figures' and '$1'" >&2; exit 1; }
         figures="$1" ;;
    esac
    shift
  done
  [[ -n "$figures" ]] || { echo "study-$STUDY: missing FIGDIR (see --help)" >&2; exit 1; }
  [[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "study-$STUDY: --jobs must be a positive integer, got '$jobs'" >&2; exit 1; }
  [[ "$ranks" =~ ^[1-9][0-9]*$ ]] || { echo "study-$STUDY: --ranks must be a positive integer, got '$ranks'" >&2; exit 1; }
  [[ "$build" = /* ]] || build="$PWD/$build"
  [[ "$figures" = /* ]] || figures="$PWD/$figures"
  if [[ -z "$runs" ]]; then
    runs="$here/out/study-$STUDY"
    [[ "$mode" == reduced ]] || runs="$runs-$mode"
  fi
  [[ "$runs" = /* ]] || runs="$PWD/$runs"
  app_path="$build/apps/$APP/$APP"
  if [[ $plot_only -eq 0 && ! -x "$app_path" ]]; then
    echo "study-$STUDY: no $app_path; build it first (cmake --build $build --target $APP) or pass --build DIR" >&2
    exit 1
  fi
  [[ -x "$python" ]] || { echo "study-$STUDY: $python is missing; run utils/install-deps.sh" >&2; exit 1; }
}

# run_deck NAME DECK [--set "Key=value"]...: runs DECK into RUNS/NAME (log RUNS/NAME.log),
# at most $jobs at a time.
run_deck() {
  local name="$1" deck="$2"
  shift 2
  [[ $plot_only -eq 0 ]] || return 0
  while [[ $(jobs -rp | wc -l) -ge $jobs ]]; do
    wait -n || true
  done
  (
    local start=$SECONDS launcher=()
    [[ $ranks -le 1 ]] || launcher=(mpiexec -n "$ranks" --oversubscribe)
    rm -rf "${runs:?}/$name"
    mkdir -p "$(dirname "$runs/$name")"
    if "${launcher[@]}" "$app_path" "$here/$deck" --output "$runs/$name" "$@" > "$runs/$name.log" 2>&1; then
      echo "  done    $name ($((SECONDS - start)) s)"
    else
      echo "  FAILED  $name ($((SECONDS - start)) s): $(grep -m1 -i "error" "$runs/$name.log" | cut -c1-160)"
      echo "$name" >> "$runs/.failed"
    fi
  ) &
}

# draw SCRIPT [ARGS...]: runs a plotting script on the runs folder.
draw() {
  local script="$1"
  shift
  if ! "$python" "$plotting/$script" --out "$figures" "$@" "$runs" | sed 's/^/  /'; then
    draw_failed=1
  fi
}

study_main() {
  parse_arguments "$@"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mkdir -p "$runs" "$figures"
  local start=$SECONDS status=0
  if [[ $plot_only -eq 0 ]]; then
    rm -f "$runs/.failed"
    echo "== $STUDY study ($mode): runs in $runs, $jobs at a time, $ranks rank(s) each"
    study_runs
    wait
    if [[ -s "$runs/.failed" ]]; then
      echo "== $(wc -l < "$runs/.failed") run(s) stopped early (see RUNS/<name>.log; docs/figures.md):"
      sed 's/^/  /' "$runs/.failed"
      status=1
    fi
    echo "== runs took $((SECONDS - start)) s"
  fi
  echo "== figures in $figures"
  # The study's own figures are drawn afresh (a stale one must not pass --check).
  for name in "${EXPECTED[@]}"; do rm -f "$figures/$name"; done
  draw_failed=0
  # The scripts import capsula_outputs from their folder; no __pycache__ in the sources.
  export PYTHONPATH="$plotting${PYTHONPATH:+:$PYTHONPATH}" PYTHONDONTWRITEBYTECODE=1
  study_figures
  [[ $draw_failed -eq 0 ]] || status=1
  if [[ $check -eq 1 ]]; then
    "$python" "$plotting/check_figures.py" "$figures" "${EXPECTED[@]}" || status=1
  fi
  echo "== $STUDY study done in $((SECONDS - start)) s (exit status $status)"
  return $status
}
