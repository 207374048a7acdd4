#!/usr/bin/env bash
# The layering of core/ (ARCHITECTURE.md), checked on the include lines of every file of every
# folder, headers included: the CMake targets enforce it only for what a source compiles.
# Usage: include_rules.sh CORE_DIR   (exit 0 when every include is allowed, 1 with the list)
set -euo pipefail
core="${1:?usage: include_rules.sh CORE_DIR}"

# Folder -> the core folders and outside layers it may include (besides itself and std).
declare -A allowed=(
  [base]=""
  [input]="base predicates"
  [mesh]="base"
  [io]="base input mesh predicates"
  [gen]="base input predicates"
  [order]="base input predicates"
  [geometry]="base input mesh predicates perturbation"
  [delaunay]="base input mesh geometry check io predicates perturbation"
  [check]="base input mesh geometry io predicates perturbation"
  [edit]="base input mesh geometry delaunay check predicates perturbation"
  [parallel]="base input mesh geometry delaunay predicates perturbation"
  [live]="base input mesh geometry delaunay check edit io parallel predicates perturbation"
  [cdt]="base input mesh order geometry delaunay check edit live io predicates perturbation boost gmp"
)

status=0
for folder in "$core"/*/; do
  module="$(basename "$folder")"
  [[ "$module" == version ]] && continue
  if [[ -z "${allowed[$module]+set}" ]]; then
    echo "core/$module: a folder with no rule (add it to ${BASH_SOURCE[0]} and ARCHITECTURE.md)"
    status=1
    continue
  fi
  while IFS= read -r line; do
    file="${line%%:*}"
    include="${line#*:}"
    case "$include" in
      *'"cavity/core/version.h"'*) continue ;;
      *'"cavity/core/'*) target="$(sed -E 's|.*"cavity/core/([a-z_]+)/.*|\1|' <<< "$include")" ;;
      *'"cavity/predicates/'*) target=predicates ;;
      *'"cavity/perturbation/'*) target=perturbation ;;
      *'<boost/'*) target=boost ;;
      *'<gmp'*) target=gmp ;;
      *) continue ;;
    esac
    if [[ "$target" != "$module" && " ${allowed[$module]} " != *" $target "* ]]; then
      echo "${file#"$core"/}: core/$module may not include $target: ${include}"
      status=1
    fi
  done < <(grep -HE '^#include' -r "$folder" --include='*.h' --include='*.cpp')
done
if [[ $status -eq 0 ]]; then
  echo "include rules: every include of core/ is allowed"
fi
exit $status
