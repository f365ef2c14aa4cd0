/* The two-axis bend sensor on I2C (TWI at 400 kHz, address 0x12) with its active-low
 * data-ready line on D2 (INT0). A read returns both axes as little-endian int16 counts of
 * SENSOR_RESOLUTION_MDEG millidegrees. */
#ifndef TENDRIL_FIRMWARE_SENSOR_H
#define TENDRIL_FIRMWARE_SENSOR_H

#include <stdint.h>

#include "clock.h"

#define SENSOR_ADDRESS 0x12
#define SENSOR_RESOLUTION_MDEG 100

void sensor_init(void);
/* 1 when a reading became ready; `*ready_at` is when (taken in the data-ready interrupt). */
uint8_t sensor_ready(struct clock_time* ready_at);
void sensor_discard(void);
/* Reads the pending reading; 0 on a bus error (no acknowledge, timeout). */
uint8_t sensor_read(int16_t angles[2]);
/* The TWI status (TWSR) at which the last failed read stopped; 0xFF for a bus timeout. */
uint8_t sensor_failed_status(void);

#endif
