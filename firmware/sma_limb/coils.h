/* The four SMA coils' MOSFET gates, 8-bit fast PWM at 16 MHz / 64 / 256 ≈ 977 Hz:
 * +x on D3 (OC2B), −x on D5 (OC0B), +y on D6 (OC0A), −y on D11 (OC2A). */
#ifndef TENDRIL_FIRMWARE_COILS_H
#define TENDRIL_FIRMWARE_COILS_H

#include <stdint.h>

void coils_init(void);
/* Duty 0 disconnects the timer from the pin, which is then held low (fast PWM at OCR = 0 would
 * still pulse once a period). */
void coils_set(const uint8_t duty[4]);
void coils_off(void);
const uint8_t* coils_duty(void);
uint8_t coils_any_on(void);

#endif
