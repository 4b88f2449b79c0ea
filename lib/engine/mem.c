/* engine/mem.c — the engine's per-ball arrays, large ones on transparent huge pages: a
 * neighbour scan reads records all over them, and once they outgrow what the TLB maps in
 * 4-KiB pages (~8 MiB) every row of a scan can cost a page walk. Memory is the same; only
 * the page size changes, so the results keep their bits. */
#include <stdint.h>
#include <stdlib.h>
#ifdef __linux__
#include <sys/mman.h>
#endif

#include "private.h"

/* The huge page size of x86-64 and arm64 Linux (4-KiB base pages). Arrays smaller than
 * one gain nothing and keep their own alignment; where the kernel uses another size or
 * has THP off, the advice is ignored and the array works as any other. */
#define HUGE_PAGE ((size_t)2 << 20)
/* Cache-line alignment for the rest: a 64-byte record never straddles two lines. */
#define LINE 64

void *eng_alloc(size_t bytes)
{
    if (bytes == 0)
        bytes = 1;
    void *p = NULL;
    if (bytes < HUGE_PAGE) {
        if (posix_memalign(&p, LINE, bytes) != 0)
            return NULL;
        return p;
    }
    if (posix_memalign(&p, HUGE_PAGE, bytes) != 0)
        return NULL;
#ifdef MADV_HUGEPAGE
    /* whole huge pages only (the tail stays in small pages, so nothing past the array is
     * ever backed); advice: on failure the array still works, in small pages */
    (void)madvise(p, bytes & ~(HUGE_PAGE - 1), MADV_HUGEPAGE);
#endif
    return p;
}
