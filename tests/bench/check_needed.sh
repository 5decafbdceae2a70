#!/bin/sh
# Fails unless the ELF file $1 needs only libvulkan.so.1 and the C runtime (libc, libm, the dynamic
# loader; libpthread/libdl on an older glibc): postfx-bench must run on a bare GPU machine.
set -eu
needed=$(readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]$/\1/p')
if [ -z "$needed" ]; then
    echo "no NEEDED entries read from $1 (is readelf installed?)"
    exit 1
fi
status=0
for lib in $needed; do
    case "$lib" in
        libvulkan.so.1 | libc.so.6 | libm.so.6 | ld-linux-*.so.* | libpthread.so.0 | libdl.so.2) echo "ok: $lib" ;;
        *) echo "unexpected dependency: $lib"; status=1 ;;
    esac
done
exit $status
