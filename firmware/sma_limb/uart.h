/* USART0 at 115200 baud (8N1), interrupt-driven both ways with ring buffers. */
#ifndef TENDRIL_FIRMWARE_UART_H
#define TENDRIL_FIRMWARE_UART_H

#include <stdint.h>

void uart_init(void);
uint8_t uart_available(void);
uint8_t uart_get(void);      /* only after uart_available() */
void uart_put(uint8_t byte); /* waits while the transmit buffer is full */
uint8_t uart_overruns(void); /* received bytes lost to a full buffer since boot */

#endif
