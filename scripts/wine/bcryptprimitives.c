/* A stand-in for Windows' bcryptprimitives.dll, for running the tests under Wine 8 ONLY:
 * Rust's standard library takes its random bytes from ProcessPrng, which Wine 8's
 * bcryptprimitives.dll lacks (Wine 9 has it; real Windows 10 and 11 have it). This one
 * forwards to advapi32's SystemFunction036 (RtlGenRandom). scripts/test-windows builds it
 * into the Wine prefix it makes under target/; it is never packaged. */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    for (SIZE_T done = 0; done < length;) {
        ULONG chunk = (length - done > 0x10000000) ? 0x10000000 : (ULONG)(length - done);
        if (!SystemFunction036(data + done, chunk)) return FALSE;
        done += chunk;
    }
    return TRUE;
}
