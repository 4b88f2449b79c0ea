#!/bin/sh
# Fails if librelcol exports a defined symbol without the rc_ prefix.
lib="$1"
bad=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBR]$/ {print $3}' | grep -v '^rc_' | grep -v '^_')
if [ -n "$bad" ]; then
  echo "symbols without the rc_ prefix:"; echo "$bad"; exit 1
fi
echo "all exported symbols carry the rc_ prefix"
