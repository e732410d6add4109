#!/usr/bin/env bash
# The bash completion offers each command's options exactly as its --help lists them, and the
# catalog's ids from `wobble list`. Usage: completion_test.sh WOBBLE_EXE COMPLETION_SCRIPT
set -euo pipefail
exe="$1"
source "$2"
PATH="$(dirname "$exe"):$PATH"
status=0
offered() {  # words... -> what _wobble offers for the last one
  COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMPREPLY=(); _wobble
  printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' '
}
for cmd in list solve check worksheet simulate bench keys serve page; do  # export: its systems below
  want=$( { "$exe" "$cmd" --help | grep -oE '^\s+--[a-z-]+' | tr -d ' '; echo --help; } | sort | tr '\n' ' ')
  got=$(offered wobble "$cmd" --)
  if [[ "$want" != "$got" ]]; then
    echo "completion: $cmd offers [$got]; its --help lists [$want]"; status=1
  fi
done
for system in prairielearn moodle gradescope; do
  want=$( { "$exe" export "$system" --help | grep -oE '^\s+--[a-z-]+' | tr -d ' '; echo --help; } | sort | tr '\n' ' ')
  got=$(offered wobble export "$system" --)
  if [[ "$want" != "$got" ]]; then
    echo "completion: export $system offers [$got]; its --help lists [$want]"; status=1
  fi
done
# The methods offered are those simulate --help names (which it takes from the method table).
want=$("$exe" simulate --help | grep -E '^\s+--method' | sed -E 's/^\s+--method TEXT\s+//; s/ \(default.*//; s/,? or / /; s/,//g' | tr ' ' '\n' | sort | tr '\n' ' ')
got=$(offered wobble simulate --method '')
[[ "$want" == "$got" ]] || { echo "completion: --method offers [$got]; simulate --help names [$want]"; status=1; }
[[ "$(offered wobble export pr)" == "prairielearn " ]] || { echo "completion: no export system"; status=1; }
[[ "$(offered wobble simulate tennis)" == "tennis-racket " ]] || { echo "completion: no scene id"; status=1; }
[[ "$(offered wobble solve flying-p)" == "flying-plate " ]] || { echo "completion: no problem id"; status=1; }
exit $status
