#include "coils.h"

#include <avr/io.h>

static uint8_t current[4];

void coils_init(void) {
  PORTD &= ~(_BV(PD3) | _BV(PD5) | _BV(PD6));
  PORTB &= ~_BV(PB3);
  DDRD |= _BV(PD3) | _BV(PD5) | _BV(PD6);
  DDRB |= _BV(PB3);
  TCCR0A = _BV(WGM01) | _BV(WGM00); /* fast PWM, outputs disconnected */
  TCCR0B = _BV(CS01) | _BV(CS00);   /* F_CPU / 64 */
  TCCR2A = _BV(WGM21) | _BV(WGM20);
  TCCR2B = _BV(CS22); /* Timer2's F_CPU / 64 */
  coils_off();
}

void coils_set(const uint8_t duty[4]) {
  uint8_t tccr0a = _BV(WGM01) | _BV(WGM00), tccr2a = _BV(WGM21) | _BV(WGM20);
  OCR2B = duty[0];
  OCR0B = duty[1];
  OCR0A = duty[2];
  OCR2A = duty[3];
  if (duty[0]) tccr2a |= _BV(COM2B1);
  if (duty[1]) tccr0a |= _BV(COM0B1);
  if (duty[2]) tccr0a |= _BV(COM0A1);
  if (duty[3]) tccr2a |= _BV(COM2A1);
  TCCR0A = tccr0a;
  TCCR2A = tccr2a;
  for (uint8_t i = 0; i < 4; ++i) current[i] = duty[i];
}

void coils_off(void) {
  static const uint8_t zero[4] = {0, 0, 0, 0};
  coils_set(zero);
}

const uint8_t* coils_duty(void) { return current; }

uint8_t coils_any_on(void) { return current[0] | current[1] | current[2] | current[3]; }
