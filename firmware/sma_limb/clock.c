#include "clock.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <util/atomic.h>

static volatile uint32_t milliseconds;

ISR(TIMER1_COMPA_vect) { ++milliseconds; }

void clock_init(void) {
  TCCR1A = 0;
  TCCR1B = _BV(WGM12) | _BV(CS11) | _BV(CS10); /* CTC on OCR1A, F_CPU / 64 = 250 kHz */
  OCR1A = 249;                                 /* 250 counts: 1 ms */
  TIMSK1 = _BV(OCIE1A);
}

struct clock_time clock_now(void) {
  struct clock_time now;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    now.ms = milliseconds;
    now.ticks = TCNT1;
    /* The counter wrapped but its interrupt is still pending: that millisecond is over. */
    if ((TIFR1 & _BV(OCF1A)) && now.ticks < 125) ++now.ms;
  }
  return now;
}

uint32_t clock_ms(void) {
  uint32_t ms;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { ms = milliseconds; }
  return ms;
}

uint32_t clock_elapsed_ms(struct clock_time earlier, struct clock_time later) {
  const int16_t microseconds = 4 * ((int16_t)later.ticks - (int16_t)earlier.ticks);
  uint32_t ms = later.ms - earlier.ms;
  if (microseconds >= 500) ++ms;
  if (microseconds < -500) --ms;
  return ms;
}
