#!/bin/sh
# run_if_exported.sh LIBRARY SYMBOL PROGRAM [ARGS...]: runs PROGRAM, or exits 77 (ctest's skip
# code) with the reason when LIBRARY does not export SYMBOL: a toolkit linked BIND_NOW (as
# freeglut is) cannot load on a Pineda build that lacks a function it imports.
lib=$1
symbol=$2
shift 2
if ! nm -D --defined-only "$lib" 2> /dev/null | grep -q " $symbol$"; then
  echo "SKIP: $lib does not export $symbol yet, which $1 needs to load"
  exit 77
fi
exec "$@"
