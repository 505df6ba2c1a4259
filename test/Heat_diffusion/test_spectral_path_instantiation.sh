#!/usr/bin/env bash
# The spectral path (the eigen solver, Spectra, the coarse level's simplification) is
# compiled only into programs whose named parameters can select it: the examples that
# use the local kernel alone must not contain a symbol of it, the one that uses the
# spectral kernel must (which shows that the check can see them).
# Usage: test_spectral_path_instantiation.sh SPECTRAL_PROGRAM LOCAL_PROGRAM...
set -euo pipefail
pattern='Spectra::|compute_smallest_generalized_eigenpairs|make_coarse_level|Surface_mesh_simplification::'
count() { nm -C "$1" | grep -cE "$pattern" || true; }
spectral=$1
shift
found=$(count "$spectral")
if [ "$found" -eq 0 ]; then
  echo "FAIL: $(basename "$spectral") uses the spectral kernel, but no symbol of the spectral path was found"
  exit 1
fi
echo "ok: $(basename "$spectral"): $found symbols of the spectral path"
status=0
for program in "$@"; do
  found=$(count "$program")
  if [ "$found" -ne 0 ]; then
    echo "FAIL: $(basename "$program") uses the local kernel only, but holds $found symbols of the spectral path:"
    nm -C "$program" | grep -E "$pattern" | head -5 || true
    status=1
  else
    echo "ok: $(basename "$program"): no symbol of the spectral path"
  fi
done
exit $status
