/* engine/queue.c — the event queue, one entry per ball popped in exact (time, ball) order: a
 * calendar queue (G. Paul, J. Comput. Phys. 221 (2007) 615), its current bucket a small heap
 * and the later ones O(1) lists, so the pop order is any exact priority queue's whatever the
 * bucket width. */
#include <math.h>
#include <stdlib.h>

#include "private.h"
#include "relcol/status.h"

/* Entries per bucket aimed at when the width is chosen: a few, so that the heap being
 * drained stays tiny while few buckets are empty. */
#define PER_BUCKET 2.0
/* Bucket numbers are kept below 2^52 so that they convert to and from double exactly;
 * a span that would pass it is rebuilt with a wider bucket. */
#define BUCKET_MAX 4503599627370496.0

/* An entry's links: in the heap next = IN_HEAP, prev = its position; in a list the following
 * and preceding balls (-1: none; HEAD(L) at list L's head). */
#define IN_HEAP INT32_MIN
#define HEAD(L) (-1 - (int32_t)(L))
#define HEAD_LIST(p) ((uint32_t)(-1 - (p)))

static inline uint32_t list_over(const eng_queue *q) { return q->nb; }
static inline uint32_t list_never(const eng_queue *q) { return q->nb + 1; }

static inline int before(const eng_queue *q, uint32_t a, uint32_t b)
{
    const double ka = q->e[a].key, kb = q->e[b].key;
    return ka < kb || (ka == kb && a < b);
}

static inline void heap_set(eng_queue *q, size_t k, uint32_t i)
{
    q->heap[k] = i;
    q->e[i].next = IN_HEAP;
    q->e[i].prev = (int32_t)k;
}

static void heap_up(eng_queue *q, size_t k)
{
    const uint32_t e = q->heap[k];
    while (k > 0) {
        const size_t parent = (k - 1) / 2;
        if (!before(q, e, q->heap[parent]))
            break;
        heap_set(q, k, q->heap[parent]);
        k = parent;
    }
    heap_set(q, k, e);
}

static void heap_down(eng_queue *q, size_t k)
{
    const uint32_t e = q->heap[k];
    for (;;) {
        size_t c = 2 * k + 1;
        if (c >= q->hn)
            break;
        if (c + 1 < q->hn && before(q, q->heap[c + 1], q->heap[c]))
            c++;
        if (!before(q, q->heap[c], e))
            break;
        heap_set(q, k, q->heap[c]);
        k = c;
    }
    heap_set(q, k, e);
}

static void heap_push(eng_queue *q, uint32_t i)
{
    q->heap[q->hn] = i; /* capacity n: every ball fits */
    heap_up(q, q->hn++);
}

static void heap_remove(eng_queue *q, size_t k)
{
    const uint32_t last = q->heap[--q->hn];
    if (k == q->hn)
        return;
    heap_set(q, k, last);
    heap_up(q, k);
    heap_down(q, (size_t)q->e[last].prev);
}

static void list_push(eng_queue *q, uint32_t L, uint32_t i)
{
    if (L == list_over(q) && q->e[i].key < q->over_min)
        q->over_min = q->e[i].key;
    const int32_t h = q->head[L];
    q->e[i].next = h;
    q->e[i].prev = HEAD(L);
    if (h >= 0)
        q->e[h].prev = (int32_t)i;
    q->head[L] = (int32_t)i;
    q->in_cal += L < q->nb;
}

/* Whether a listed entry is in a calendar list, from its key: place() files there exactly when
 * its bucket lies before redist. */
static inline int in_calendar(const eng_queue *q, double t)
{
    return t * q->inv_w < (double)q->redist; /* (inf and NaN: no) */
}

static void list_unlink(eng_queue *q, uint32_t i)
{
    const int32_t p = q->e[i].prev, nx = q->e[i].next;
    if (p >= 0)
        q->e[p].next = nx;
    else
        q->head[HEAD_LIST(p)] = nx;
    if (nx >= 0)
        q->e[nx].prev = p; /* (the new head takes the list's mark) */
    q->in_cal -= (size_t)in_calendar(q, q->e[i].key);
}

/* File ball i by its key: the heap (its bucket the current one or earlier), its calendar list
 * (within the span), else overflow (never: no event). */
static void place(eng_queue *q, uint32_t i)
{
    const double t = q->e[i].key;
    const double x = t * q->inv_w; /* bucket floor(x); bucket numbers are exact doubles */
    if (!(x < (double)q->redist)) { /* also inf and NaN */
        list_push(q, t < INFINITY ? list_over(q) : list_never(q), i);
        return;
    }
    if (x < (double)q->cur + 1.0) { /* floor(x) <= cur */
        heap_push(q, i);
        return;
    }
    /* cur + 1 <= x < redist <= cur + nb: truncation is floor when x >= 0 (no libm call) */
    const int64_t b = x >= 0.0 ? (int64_t)x : (int64_t)floor(x);
    list_push(q, (uint32_t)(b & (int64_t)(q->nb - 1)), i);
}

/* A new span [cur, cur + nb) with an empty overflow list, which the caller fills again;
 * returns the list it held. */
static int32_t new_span(eng_queue *q)
{
    const int32_t k = q->head[list_over(q)];
    q->head[list_over(q)] = -1;
    q->over_min = INFINITY;
    q->redist = q->cur + (int64_t)q->nb;
    return k;
}

/* Spread the overflow list over the calendar's new span [cur, cur + nb). */
static void redistribute(eng_queue *q)
{
    int32_t k = new_span(q);
    while (k >= 0) {
        const int32_t nx = q->e[k].next;
        place(q, (uint32_t)k);
        k = nx;
    }
}

/* The same when the calendar lists and heap are empty: entries read in array order, which the
 * hardware streams, not along the list (a miss per entry at N = 1e6); pop order unchanged. */
static void redistribute_all(eng_queue *q)
{
    (void)new_span(q);
    for (size_t i = 0; i < q->n; i++)
        if (q->e[i].key < INFINITY)
            place(q, (uint32_t)i);
}

int eng_queue_init(eng_queue *q, size_t n)
{
    q->n = n;
    q->nb = 1;
    while (2 * (size_t)q->nb <= n / 2 + 1) /* nb ~ n/4 .. n/2: a few bytes per ball */
        q->nb *= 2;
    const size_t m = n ? n : 1;
    q->e = eng_alloc(m * sizeof *q->e);
    q->heap = eng_alloc(m * sizeof *q->heap);
    q->head = malloc(((size_t)q->nb + 2) * sizeof *q->head);
    if (!q->e || !q->heap || !q->head) {
        eng_queue_free(q);
        return RC_ENOMEM;
    }
    q->hn = 0;
    q->over_min = INFINITY;
    q->ahead = -1;
    return RC_OK;
}

void eng_queue_free(eng_queue *q)
{
    free(q->e);
    free(q->heap);
    free(q->head);
    *q = (eng_queue){0};
}

/* Every entry again, the bucket width fitted to ~PER_BUCKET entries near now from the mean
 * lead of the finite keys. */
static void rebuild(eng_queue *q, double now)
{
    double lead = 0.0, far = now;
    size_t nf = 0;
    for (size_t i = 0; i < q->n; i++) {
        const double t = q->e[i].key;
        if (t < INFINITY) {
            lead += t > now ? t - now : 0.0;
            far = t > far ? t : far;
            nf++;
        }
    }
    double w = nf && lead > 0.0 ? PER_BUCKET * (lead / (double)nf) / (double)nf : 1.0;
    /* bucket numbers of now and of every finite key stay exact (and w > 0, finite) */
    const double span = fabs(now) > fabs(far) ? fabs(now) : fabs(far);
    if (!(w >= span / BUCKET_MAX) || !(w > 0.0))
        w = span > 0.0 ? span / BUCKET_MAX * 2.0 : 1.0;
    if (!isfinite(w))
        w = 1.0;
    q->inv_w = 1.0 / w;
    q->cur = (int64_t)floor(now * q->inv_w);
    q->redist = q->cur + (int64_t)q->nb;
    q->hn = 0;
    q->in_cal = 0;
    q->over_min = INFINITY;
    for (uint32_t L = 0; L < q->nb + 2; L++)
        q->head[L] = -1;
    for (size_t i = q->n; i-- > 0;)
        place(q, (uint32_t)i);
}

void eng_queue_build(eng_queue *q, const double *keys, double now)
{
    for (size_t i = 0; i < q->n; i++)
        q->e[i].key = keys[i];
    rebuild(q, now);
}

void eng_queue_rebuild(eng_queue *q, double now)
{
    rebuild(q, now);
}

void eng_queue_update(eng_queue *q, uint32_t ball, double t)
{
    eng_qent *e = &q->e[ball];
    if (e->next == IN_HEAP) { /* in the heap: most updates are of the ball just popped */
        if (t * q->inv_w < (double)q->cur + 1.0) { /* still the current bucket */
            const double old = e->key;
            e->key = t;
            if (t < old)
                heap_up(q, (size_t)e->prev);
            else
                heap_down(q, (size_t)e->prev);
            return;
        }
        heap_remove(q, (size_t)e->prev);
    } else {
        list_unlink(q, ball);
    }
    e->key = t;
    place(q, ball);
}

int eng_queue_top(eng_queue *q, double *t, uint32_t *ball)
{
    /* one step along the next bucket's list per call: its entries are in cache by the
     * time it is drained (a hint: the list may have changed since, any ball will do) */
    if (q->ahead >= 0) {
        q->ahead = q->e[q->ahead].next;
        if (q->ahead >= 0)
            __builtin_prefetch(&q->e[q->ahead]);
    }
    while (q->hn == 0) {
        if (q->in_cal == 0) {
            /* nothing within the span: start it at the earliest overflow entry */
            int32_t k = q->head[list_over(q)];
            if (k < 0) { /* no finite event left: any ball, at infinity */
                const int32_t never = q->head[list_never(q)];
                if (never < 0)
                    return 0;
                *t = INFINITY;
                *ball = (uint32_t)never;
                return 1;
            }
            /* the earliest overflow key or a bound below it (over_min), so the list is not
             * walked (a miss per entry at N = 1e6) */
            double tmin = q->over_min;
            if (!(tmin < INFINITY))
                for (; k >= 0; k = q->e[k].next)
                    tmin = q->e[k].key < tmin ? q->e[k].key : tmin;
            const double b = floor(tmin * q->inv_w);
            if (!(fabs(b) < BUCKET_MAX - (double)q->nb)) {
                rebuild(q, tmin); /* beyond exact bucket numbers: a wider width */
                continue;
            }
            q->cur = (int64_t)b;
            redistribute_all(q);
            continue;
        }
        q->cur++;
        if (q->cur >= q->redist)
            redistribute(q);
        /* drain the new current bucket into the heap */
        const uint32_t L = (uint32_t)(q->cur & (int64_t)(q->nb - 1));
        int32_t k = q->head[L];
        q->head[L] = -1;
        q->ahead = q->head[(L + 1) & (q->nb - 1)];
        if (q->ahead >= 0)
            __builtin_prefetch(&q->e[q->ahead]);
        while (k >= 0) {
            const int32_t nx = q->e[k].next;
            q->in_cal--;
            heap_push(q, (uint32_t)k);
            k = nx;
        }
    }
    *t = q->e[q->heap[0]].key;
    *ball = q->heap[0];
    return 1;
}

size_t eng_queue_bytes(const eng_queue *q)
{
    return q->n * (sizeof *q->e + sizeof *q->heap) + ((size_t)q->nb + 2) * sizeof *q->head;
}
