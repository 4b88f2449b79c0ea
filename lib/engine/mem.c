/* engine/mem.c — large per-ball arrays on transparent huge pages: a scan reads them all over,
 * and past ~8 MiB of 4-KiB pages each row can cost a page walk; same memory, same bits. */
#include <stdint.h>
#include <stdlib.h>
#ifdef __linux__
#include <sys/mman.h>
#endif

#include "private.h"

/* The huge page size of x86-64 and arm64 Linux; smaller arrays keep their alignment, and with
 * THP off the advice is ignored. */
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
