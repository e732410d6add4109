# bash completion for wobble: commands, their options, and problem or scene ids (from
# `wobble list`, so an installed program completes its own catalog).
_wobble() {
  local cur prev cmd
  cur="${COMP_WORDS[COMP_CWORD]}"
  prev="${COMP_WORDS[COMP_CWORD-1]}"
  cmd=""
  local i
  for ((i = 1; i < COMP_CWORD; i++)); do
    case "${COMP_WORDS[i]}" in
      list|solve|keys|simulate|bench|check|worksheet|export|serve|page) cmd="${COMP_WORDS[i]}"; break ;;
    esac
  done
  if [[ -z "$cmd" ]]; then
    if [[ "$prev" == --data-dir ]]; then
      COMPREPLY=($(compgen -d -- "$cur"))
    else
      COMPREPLY=($(compgen -W "list solve check worksheet simulate bench keys export serve page --data-dir --help --version" -- "$cur"))
    fi
    return
  fi
  case "$prev" in
    --out|--plot|--figure|--answers|--deb) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --problems) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    --format) COMPREPLY=($(compgen -W "text markdown latex json csv gradescope" -- "$cur")); return ;;
    --method) COMPREPLY=($(compgen -W "auto closed_form exact rk4 dopri5 rkf78 dop853 vern9 split2 split4" -- "$cur")); return ;;
    --problem) COMPREPLY=($(compgen -W "$(_wobble_ids problems)" -- "$cur")); return ;;
  esac
  local options
  case "$cmd" in
    solve) options="--set --variant --format --part --handout --figure --force --cross-check --help" ;;
    check) options="--answer --answers --format --name --set --variant --tolerance --sigfigs --help" ;;
    list) options="--solvers --help" ;;
    serve) options="--host --port --problems --reveal --help" ;;
    page) options="--variant --key --no-hints --out --force --help" ;;
    worksheet) options="--variant --set --help" ;;
    simulate) options="--set --variant --method --tolerance --samples --t-end --max-evaluations --out --plot --force --help" ;;
    bench) options="--quick --format --plot --force --help" ;;
    keys) options="--check --update --variants --out --problem --force --help" ;;
    export)
      local system="${COMP_WORDS[i+1]}"
      case "$system" in
        prairielearn) options="--variants --out --force --tolerance --sigfigs --help" ;;
        moodle) options="--variants --out --force --tolerance --help" ;;
        gradescope) options="--out --deb --force --tolerance --help" ;;
        *) COMPREPLY=($(compgen -W "prairielearn moodle gradescope --help" -- "$cur")); return ;;
      esac ;;
    *) options="--help" ;;
  esac
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
  elif [[ "$cmd" == simulate ]]; then
    COMPREPLY=($(compgen -W "$(_wobble_ids scenes)" -- "$cur"))
  elif [[ "$cmd" =~ ^(solve|check|worksheet|export|page)$ ]]; then
    COMPREPLY=($(compgen -W "$(_wobble_ids problems)" -- "$cur"))
  fi
}

# The ids under the "problems" or "scenes" heading of `wobble list`.
_wobble_ids() {
  "${COMP_WORDS[0]}" list 2>/dev/null | awk -v want="$1" '/^[a-z]/ {on = ($1 == want)} /^  / && on {print $1}'
}

complete -F _wobble wobble
