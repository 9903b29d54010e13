#!/usr/bin/env bash
# Every script under utils/ answers --help: exit status 0 and a usage text. Shell scripts are
# the *.sh files with a #! line (study-lib.sh is sourced, not run); Python scripts are the
# *.py files with a __main__ block (the others are modules).
set -uo pipefail
root=${1:?repository root}
good=0
bad=0
while IFS= read -r -d '' script; do
  case $script in
    *.sh) head -1 "$script" | grep -q '^#!' || continue; command=(bash "$script" --help) ;;
    *.py) grep -q '__main__' "$script" || continue; command=(/usr/bin/python3 "$script" --help) ;;
  esac
  if output=$(PYTHONDONTWRITEBYTECODE=1 "${command[@]}" 2>&1) && grep -qi 'usage' <<< "$output"; then
    good=$((good + 1))
  else
    echo "NO HELP: ${script#"$root"/}: $(head -3 <<< "$output" | tr '\n' ' ')"
    bad=$((bad + 1))
  fi
done < <(find "$root/utils" \( -name '*.sh' -o -name '*.py' \) -print0 | sort -z)
echo "$good scripts answer --help, $bad do not"
[[ $bad -eq 0 ]]
