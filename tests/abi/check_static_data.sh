#!/bin/sh
# The library holds no writable static data: the only symbols in .data, .bss, .tdata and .tbss of
# the shared object are the ones the toolchain puts there: its start-up files, and libgcc's CPU
# feature record (__cpu_model, __cpu_features2), filled once at load time for the ifunc dispatch
# of the evaluation loops (lib/core/kernels.h, BSI_HOT).
#   check_static_data.sh LIBRARY
set -eu
lib=$1
allowed='^(__cpu_model|__cpu_features2|completed\.[0-9]+|__dso_handle|__TMC_END__|__data_start|data_start|__bss_start|_edata|_end|__TMC_LIST__)$'
found=$(objdump -t "$lib" | awk '$0 ~ /[ \t]\.(data|bss|tdata|tbss)[ \t]/ { print $NF }')
if [ -z "$found" ] && ! objdump -h "$lib" | grep -q ' \.data '; then
  echo "no symbol table in $lib: cannot check" >&2
  exit 1
fi
ours=$(printf '%s\n' "$found" | grep -Ev "$allowed" | grep -v '^$' || true)
for sec in .data .bss .tdata .tbss; do
  size=$(size -A "$lib" | awk -v s="$sec" '$1 == s { print $2 }')
  echo "$sec: ${size:-absent} bytes"
done
if [ -n "$ours" ]; then
  echo "writable static data of the library:"
  printf '  %s\n' $ours
  exit 1
fi
echo "no writable static data beyond the toolchain's ($(printf '%s\n' "$found" | grep -c . || true) toolchain symbols)"
