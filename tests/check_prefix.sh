#!/bin/sh
# check_prefix.sh LIB — fails if librelcol exports a defined symbol without the rc_ prefix,
# (the engine's internal eng_* among them), or one of the functions its files share among
# themselves (the kinematics' rc_boost_g): the exports are the public headers' names
# (lib/public-symbols.sh).
lib="$1"
syms=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBR]$/ {print $3}')
bad=$(echo "$syms" | grep -v '^rc_' | grep -v '^_')
if [ -n "$bad" ]; then
  echo "symbols without the rc_ prefix:"; echo "$bad"; exit 1
fi
internal=$(echo "$syms" | grep -E '^rc_boost_g$')
if [ -n "$internal" ]; then
  echo "internal functions exported:"; echo "$internal"; exit 1
fi
echo "all $(echo "$syms" | wc -l) exported symbols carry the rc_ prefix; no internal one is exported"
