#include "sensor.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <util/atomic.h>
#include <util/twi.h>

static volatile uint8_t ready;
static volatile struct clock_time ready_time;

ISR(INT0_vect) {
  ready_time = clock_now();
  ready = 1;
}

void sensor_init(void) {
  DDRD &= ~_BV(PD2);
  PORTD |= _BV(PD2);          /* pull-up on the open-drain data-ready line */
  EICRA = _BV(ISC01);         /* INT0 on a falling edge */
  EIMSK = _BV(INT0);
  TWSR = 0;                   /* prescaler 1 */
  TWBR = (F_CPU / 400000 - 16) / 2; /* 400 kHz */
}

uint8_t sensor_ready(struct clock_time* ready_at) {
  uint8_t is_ready;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
    is_ready = ready;
    if (is_ready) {
      ready_at->ms = ready_time.ms;
      ready_at->ticks = ready_time.ticks;
    }
  }
  return is_ready;
}

void sensor_discard(void) { ready = 0; }

/* The read runs in the TWI interrupt, one bus step per interrupt (the datasheet's master
 * receiver, §22.7.2): START, SLA+R, three bytes with ACK, the last with NACK, STOP. */
enum { TWI_IDLE, TWI_BUSY, TWI_DONE, TWI_FAILED };
static volatile uint8_t twi_state = TWI_IDLE;
static volatile uint8_t twi_bytes[4];
static volatile uint8_t twi_count;
static volatile uint8_t failed_status;

#define TWI_STEP (_BV(TWINT) | _BV(TWEN) | _BV(TWIE))

ISR(TWI_vect) {
  switch (TW_STATUS) {
    case TW_START:
      TWDR = (SENSOR_ADDRESS << 1) | TW_READ;
      TWCR = TWI_STEP;
      break;
    case TW_MR_SLA_ACK:
      TWCR = TWI_STEP | _BV(TWEA);
      break;
    case TW_MR_DATA_ACK:
      twi_bytes[twi_count++] = TWDR;
      TWCR = TWI_STEP | (twi_count < 3 ? _BV(TWEA) : 0);
      break;
    case TW_MR_DATA_NACK:
      twi_bytes[twi_count++] = TWDR;
      TWCR = _BV(TWINT) | _BV(TWEN) | _BV(TWSTO);
      twi_state = twi_count == 4 ? TWI_DONE : TWI_FAILED;
      break;
    default: /* no acknowledge, arbitration lost, bus error */
      failed_status = TW_STATUS;
      TWCR = _BV(TWINT) | _BV(TWEN) | _BV(TWSTO);
      twi_state = TWI_FAILED;
  }
}

uint8_t sensor_failed_status(void) { return failed_status; }

uint8_t sensor_read(int16_t angles[2]) {
  ready = 0;
  twi_count = 0;
  failed_status = 0xFF; /* a bus timeout unless the interrupt says otherwise */
  twi_state = TWI_BUSY;
  TWCR = _BV(TWINT) | _BV(TWSTA) | _BV(TWEN) | _BV(TWIE);
  /* Six bus steps of 9 clocks at 400 kHz take ~0.14 ms; give up after 2 ms. */
  const uint32_t began = clock_ms();
  while (twi_state == TWI_BUSY && clock_ms() - began < 3) {
  }
  if (twi_state != TWI_DONE) {
    TWCR = _BV(TWINT) | _BV(TWEN) | _BV(TWSTO);
    twi_state = TWI_IDLE;
    return 0;
  }
  twi_state = TWI_IDLE;
  angles[0] = (int16_t)(twi_bytes[0] | (twi_bytes[1] << 8));
  angles[1] = (int16_t)(twi_bytes[2] | (twi_bytes[3] << 8));
  return 1;
}
