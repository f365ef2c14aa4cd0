/* Time since boot from Timer1: a 1 kHz tick (CTC, prescaler 64) and its 4 µs counter. */
#ifndef TENDRIL_FIRMWARE_CLOCK_H
#define TENDRIL_FIRMWARE_CLOCK_H

#include <stdint.h>

struct clock_time {
  uint32_t ms;    /* whole milliseconds since boot */
  uint16_t ticks; /* 4 µs ticks into the current millisecond, 0–249 */
};

void clock_init(void);
struct clock_time clock_now(void);
uint32_t clock_ms(void);
/* (later − earlier) rounded to whole milliseconds. */
uint32_t clock_elapsed_ms(struct clock_time earlier, struct clock_time later);

#endif
