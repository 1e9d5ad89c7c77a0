#!/usr/bin/env bash
# Checks what libstrata_core exports (strata/export.hpp): what the SDK's headers declare, and not the
# library's internals nor the instantiations of the libraries it uses.
#   exports_check.sh LIBSTRATA_CORE
set -euo pipefail

source "$(dirname "$0")/sdk_test_functions.sh"
exported=$(mktemp)
names=$(mktemp)
trap 'rm -f "$exported" "$names"' EXIT
nm -DC --defined-only "$1" | cut -d ' ' -f 3- >"$exported"
# Each symbol's own name: template arguments and parameters taken away, so that an instantiation of the
# standard library's templates over a yaml-cpp type (weak, and in every module that makes it) does not
# count as yaml-cpp's.
sed -E ':strip; s/<[^<>]*>//g; t strip; s/\(.*//' "$exported" >"$names"
echo "$(wc -l <"$exported") symbols exported; $(grep -c '^strata::' "$names") of them Strata's"

step "the SDK's declarations are exported"
for symbol in 'strata::Engine::render(int, int)' 'strata::Error::Error(' 'typeinfo for strata::Layer' \
              'strata::heightSlopesGlsl(' 'strata::PluginRegistry::loadModule('; do
  grep -F -- "$symbol" "$exported" >/dev/null || fail "$1 does not export $symbol"
  echo "exported: $symbol"
done

step "the internals and the instantiations of GDAL, PROJ, yaml-cpp and OpenColorIO are not"
for prefix in 'strata::NodeGraph::' 'strata::WorkerPool::' 'YAML::' 'OpenColorIO' 'OGR' 'GDAL' 'proj_'; do
  if grep -E -- "(^| )$prefix" "$names" >/dev/null; then
    grep -E -- "(^| )$prefix" "$names" | head -5
    fail "$1 exports symbols of $prefix"
  fi
  echo "hidden: $prefix"
done
