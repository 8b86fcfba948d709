#!/usr/bin/env bash
# Renders the results pages from the kept runs in results/runs/: docs/results.md, the headline page (where TC-SB
# pays: one row per kept run with curves of error against time, the verdict on a 2x speed-up, the Pareto figures,
# then every kept run), the full render of each kept run beside it (results/runs/NAME.md, by `tcsb export FILE
# --format markdown`), the tax of each pooled directory (results/runs/pooled/DIR.md) and the README's excerpt of the
# headline table (between its headline-begin and headline-end markers).
#
# Kept runs: files are named <date>-<short commit>-<suite>.json, and only the newest of each suite (by name, C
# collation) is kept; an older one must leave the tree (git keeps it), and the script refuses to render while it is
# there. The same holds for the pooled directories results/runs/pooled/<date>-<short commit>-<suite>/.
#
# Usage: bash scripts/render-results.sh [--check] [TCSB_BINARY]
#   TCSB_BINARY  the tcsb executable (default: build/tcsb)
#   --check      render to temporary files and compare them with the committed ones instead of writing:
#                exit 0 when equal, 1 with the diff when they differ (the CTest docs.results_md_is_rendered)
# Exit codes: 0 written, or equal; 1 --check found a difference, or a superseded run is still in the tree; 2 bad usage,
# no tcsb executable, or a result file tcsb refuses (its one-line message names the file); 3 a page could not be
# written.
# TCSB_RUNS_DIR, TCSB_RESULTS_MD and TCSB_README override the paths (scripts/render-results-self-test.sh uses them).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

usage() {
  echo "usage: bash scripts/render-results.sh [--check] [TCSB_BINARY]" >&2
  exit 2
}

check=0
binary=""
for arg in "$@"; do
  case $arg in
    --check) check=1 ;;
    -h | --help)
      sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    -*)
      echo "render-results: unknown option $arg" >&2
      usage
      ;;
    *)
      [[ -z $binary ]] || usage
      binary=$arg
      ;;
  esac
done
binary=${binary:-$root/build/tcsb}
runs_dir=${TCSB_RUNS_DIR:-$root/results/runs}
target=${TCSB_RESULTS_MD:-$root/docs/results.md}
readme=${TCSB_README:-$root/README.md}
if [[ ! -x $binary ]]; then
  echo "render-results: no tcsb executable at $binary (build it, or pass its path)" >&2
  exit 2
fi
binary=$(realpath "$binary") # the pooled sections run it from their own directory

# The suites whose headline rows the README shows (each under every model it was run with).
readme_suites=" viewer-corner drape "

suite_of() { # <date>-<commit>-<suite>[.json] -> <suite>
  local name=${1%.json}
  echo "${name#*-*-*-*-}"
}

# The newest entry of each suite among the names on stdin, in suite order, on stdout; a superseded one is named on
# stderr and makes the function fail.
kept_of() {
  local names=() kept=() name suite seen=" " superseded=0
  mapfile -t names < <(LC_ALL=C sort -r) # the newest first
  for name in "${names[@]}"; do
    suite=$(suite_of "$name")
    if [[ $seen == *" $suite "* ]]; then
      echo "render-results: $name is superseded by a newer run of suite $suite: remove it (git keeps it)" >&2
      superseded=1
      continue
    fi
    seen+="$suite "
    kept+=("$name")
  done
  ((${#kept[@]} == 0)) || printf '%s\n' "${kept[@]}" | LC_ALL=C sort -t- -k5
  return $superseded
}

runs=()
pooled=()
if [[ -d $runs_dir ]]; then
  kept=$(find "$runs_dir" -maxdepth 1 -type f -name '*.json' -printf '%f\n' | kept_of) || exit 1
  [[ -z $kept ]] || mapfile -t runs <<<"$kept"
  if [[ -d $runs_dir/pooled ]]; then
    kept=$(find "$runs_dir/pooled" -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | kept_of) || exit 1
    [[ -z $kept ]] || mapfile -t pooled <<<"$kept"
  fi
fi
# A kept run is of a bundled suite, from a build of a clean tree: a run no one can rerun is not a result.
for f in "${runs[@]}"; do
  if [[ ! -f $root/suites/$(suite_of "$f").json ]]; then
    echo "render-results: $f is a run of suite $(suite_of "$f"), which suites/ no longer has: remove it" >&2
    exit 1
  fi
  if grep -q '"git_commit": *"[0-9a-f]*-dirty"' "$runs_dir/$f"; then
    echo "render-results: $f was built from a tree with uncommitted changes (-dirty): remove it" >&2
    exit 1
  fi
done

# The headline table's rows of the kept runs that drew curves (or, for a file without them, the line saying so),
# each ending with its kept run's full render. $1: only the suites of $readme_suites.
headline_rows() {
  local f row
  echo '| scene | model | steered by | net, error | TC-SB at 30 %: step ms, error | vs best uniform grid (many bodies: discrete LOD) at 30 % | vs full resolution at 30 % | best vs uniform grid (discrete LOD) | kept run |'
  echo '|---|---|---|---|---|---|---|---|---|'
  for f in "${runs[@]}"; do
    [[ -n ${1:-} && $readme_suites != *" $(suite_of "$f" | sed 's/-compliant$//') "* ]] && continue
    grep -q '"equal_error"' "$runs_dir/$f" || continue
    row=$("$binary" export "$runs_dir/$f" --format markdown-headline) || return $?
    echo "$row [${f%.json}](${2:-..}/results/runs/${f%.json}.md) |"
  done
}

# A section of the figures PREFIX_SUITE.png that exist for the kept runs' suites: $1 the prefix, $2 the heading, $3
# the text before the pictures; nothing when there are none.
figure_section() {
  local f suite found=()
  for f in "${runs[@]}"; do
    suite=$(suite_of "$f")
    [[ -f $root/results/figures/$1_$suite.png ]] && found+=("$suite")
  done
  ((${#found[@]} > 0)) || return 0
  printf '\n### %s\n\n%s\n\n' "$2" "$3"
  for suite in "${found[@]}"; do
    printf '![%s](../results/figures/%s_%s.png)\n' "$suite" "$1" "$suite"
  done
}

# The headline page on stdout.
render_page() {
  cat <<'PREAMBLE'
# Results

Generated by scripts/render-results.sh from results/runs/; do not edit by hand.

The kept runs are the newest run of each suite in results/runs/ (`<date>-<short commit>-<suite>.json`); older runs
leave the tree and git keeps them. Each kept run's full render (its source line with date, commit, machine and load,
every table) is beside it as `results/runs/<name>.md`. To add a run, put its file there, `git rm` the run it
supersedes and run `bash scripts/render-results.sh`. How the numbers are measured: [methodology.md](methodology.md).
The paper's own numbers were measured with Bullet 2.78 on other hardware: only same-run ratios compare. Runs an
investigation names that have left the tree are in git: `git log --diff-filter=D --name-only -- results/runs`.
PREAMBLE
  if ((${#runs[@]} == 0)); then
    printf '\nNo runs are stored in results/runs/ yet.\n'
    return 0
  fi
  local rows verdicts f suite
  rows=$(headline_rows) || return $?
  cat <<'HEAD'

## Where TC-SB pays

The field's figure for adaptive cloth: the speed-up at equal error. For the error TC-SB reaches at a node budget,
the step time a rival needs to reach the same error, read off the rival's curve of error against step time
(log-log interpolation between its two points around that error, never extrapolated), over TC-SB's step time.
Rivals: the best uniform grid (the static grids of 10 to 75 % of the nodes, full resolution as the finest) and full
resolution with fewer solver passes (a half, a quarter, an eighth of the suite's iterations or small steps). Error:
the mean over the steps of the per-step p95 pixel error in a scene with a camera, else the mean RMS in % of the
net's extent, both against the reference (full resolution; under the compliant material, its converged small
steps). Each row: the suite's largest net; times are medians over the fidelity pass's interleaved blocks of 20
steps, intervals 95 % bootstrap over those blocks. "≤": TC-SB is less accurate than the rival's cheapest point, so
the ratio is a bound. Each row's command is `tcsb run SCENE`.

HEAD
  echo "$rows"
  if ((${#rows} > 0)) && [[ $(echo "$rows" | wc -l) -gt 2 ]]; then
    printf '\nWhere the speed-up at equal error against the best uniform grid reaches 2× (Koh et al. 2014 report\n'
    printf '2–4× for view-dependent over view-independent adaptivity), at any budget of the largest net:\n\n'
    for f in "${runs[@]}"; do
      grep -q '"equal_error"' "$runs_dir/$f" || continue
      "$binary" export "$runs_dir/$f" --format markdown-verdict || return $?
    done
    figure_section pareto "Error against step time" \
      "Per scene, its largest net (log-log): TC-SB across budgets, the uniform grids, full resolution at fewer passes
(scripts/render-figures.py, from the kept run)."
    figure_section shaded "Through the camera" \
      "Per scene with a camera, its last recorded step: full resolution, TC-SB at 30 % (its levels coloured) and the
uniform grid of its node count, shaded, and each one's pixel error against full resolution (scripts/render-figures.py,
from the newest \`tcsb frames\` of the scene in results/runs/frames/)."
  fi
  printf '\n## Every kept run\n\n'
  for f in "${runs[@]}"; do
    printf -- '- %s: [%s](../results/runs/%s.md) ([JSON](../results/runs/%s))\n' "$(suite_of "$f")" "${f%.json}" \
      "${f%.json}" "$f"
  done
  if ((${#pooled[@]} > 0)); then
    printf '\nPooled runs (the tax of adaptivity over runs each in its own process, `tcsb tax`):\n\n'
    for f in "${pooled[@]}"; do
      printf -- '- %s: [%s](../results/runs/pooled/%s.md)\n' "$(suite_of "$f")" "$f" "$f"
    done
  fi
}

# One pooled directory's section: the tax of adaptivity judged over all its runs, once with tcsb tax's defaults (the
# scaling target) or, when the directory has a file tax.args, once per line of it with that line's flags.
render_pooled() {
  local d=$1 runs_in=() flag_lines=("") flags
  mapfile -t runs_in < <(find "$runs_dir/pooled/$d" -maxdepth 1 -type f -name '*.json' -printf '%f\n' | LC_ALL=C sort)
  [[ -f $runs_dir/pooled/$d/tax.args ]] && mapfile -t flag_lines <"$runs_dir/pooled/$d/tax.args"
  printf '# Pooled runs: %s\n\nGenerated by scripts/render-results.sh; do not edit by hand.\n\n' "$d"
  printf '%s runs of the suite, each in its own process, in [%s](%s/); ' "${#runs_in[@]}" "$d" "$d"
  printf 'the tax of adaptivity over them ([methodology.md](../../../docs/methodology.md#the-tax-across-runs)):\n'
  for flags in "${flag_lines[@]}"; do
    local table status=0 args=()
    read -ra args <<<"$flags"
    # The verdict is the command's exit code (0 pass, 1 fail, 4 undecided); any other means it could not judge.
    table=$(cd "$runs_dir/pooled/$d" && "$binary" tax "${runs_in[@]}" "${args[@]}" 2>&1 >/dev/null) || status=$?
    if ((status != 0 && status != 1 && status != 4)); then
      echo "$table" >&2
      return $((status == 2 ? 2 : 3))
    fi
    printf '\n```\n$ tcsb tax %s%s\n%s\n```\n' "${runs_in[*]}" "${flags:+ $flags}" "$table"
  done
}

# The README with its headline excerpt replaced (the lines between the markers), on stdout.
render_readme() {
  local rows
  rows=$(headline_rows readme docs/..) || return $?
  rows=$(echo "$rows" | sed 's#(docs/\.\./#(#')
  awk -v rows="$rows" '
    /^<!-- headline-begin/ { print; print rows; skip = 1; next }
    /^<!-- headline-end/ { skip = 0 }
    !skip { print }' "$readme"
}

# Every page as (target, producer) pairs.
pages=("$target" render_page)
for f in "${runs[@]}"; do
  pages+=("$runs_dir/${f%.json}.md" "render_run $f")
done
for f in "${pooled[@]}"; do
  pages+=("$runs_dir/pooled/$f.md" "render_pooled $f")
done
[[ -f $readme ]] && grep -q '^<!-- headline-begin' "$readme" && pages+=("$readme" render_readme)

render_run() {
  printf '<!-- Generated by scripts/render-results.sh from %s; do not edit by hand. -->\n\n' "$1"
  "$binary" export "$runs_dir/$1" --format markdown
}

# A rendered page with no file of its own in the tree: a render of a run that left it.
stale=()
for md in "$runs_dir"/*.md "$runs_dir"/pooled/*.md; do
  [[ -f $md ]] || continue
  found=0
  for ((i = 0; i < ${#pages[@]}; i += 2)); do [[ ${pages[i]} == "$md" ]] && found=1; done
  ((found)) || stale+=("$md")
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for ((i = 0; i < ${#pages[@]}; i += 2)); do
  ${pages[i + 1]} >"$tmp/$((i / 2))" || exit $?
done

if ((check)); then
  status=0
  for ((i = 0; i < ${#pages[@]}; i += 2)); do
    page=${pages[i]}
    if [[ ! -f $page ]]; then
      echo "render-results: $page is missing; run: bash scripts/render-results.sh" >&2
      status=1
    elif ! diff -u --label "$page (committed)" --label "rendered from $runs_dir" "$page" "$tmp/$((i / 2))"; then
      echo "render-results: $page differs from what $runs_dir renders; run: bash scripts/render-results.sh" >&2
      status=1
    fi
  done
  for md in "${stale[@]}"; do
    echo "render-results: $md renders no kept run; run: bash scripts/render-results.sh" >&2
    status=1
  done
  exit $status
fi

# Each written next to its target and renamed over it, so a refused file or a full disk never leaves half a page.
for ((i = 0; i < ${#pages[@]}; i += 2)); do
  page=${pages[i]}
  staged=$(mktemp "$(dirname "$page")/.$(basename "$page").XXXXXX") || exit 3
  cp "$tmp/$((i / 2))" "$staged" && chmod 644 "$staged" && mv "$staged" "$page" || {
    rm -f "$staged"
    exit 3
  }
done
for md in "${stale[@]}"; do rm -f "$md"; done
echo "render-results: wrote $target and the renders of ${#runs[@]} kept runs" >&2
