#include "uart.h"

#include <avr/interrupt.h>
#include <avr/io.h>

#define RX_SIZE 128 /* powers of two: the indices wrap by masking */
#define TX_SIZE 128

static volatile uint8_t rx[RX_SIZE], tx[TX_SIZE];
static volatile uint8_t rx_head, rx_tail, tx_head, tx_tail, overruns;

void uart_init(void) {
  /* U2X: UBRR = F_CPU / (8 · 115200) − 1 = 16 at 16 MHz (117.6 kBd, 2.1 % fast, as the
   * Arduino core runs it). */
  UCSR0A = _BV(U2X0);
  UBRR0 = (F_CPU / 8 / 115200) - 1;
  UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);
  UCSR0B = _BV(RXEN0) | _BV(TXEN0) | _BV(RXCIE0);
}

ISR(USART_RX_vect) {
  const uint8_t byte = UDR0;
  const uint8_t next = (rx_head + 1) & (RX_SIZE - 1);
  if (next == rx_tail) {
    ++overruns;
    return;
  }
  rx[rx_head] = byte;
  rx_head = next;
}

ISR(USART_UDRE_vect) {
  if (tx_head == tx_tail) {
    UCSR0B &= ~_BV(UDRIE0);
    return;
  }
  UDR0 = tx[tx_tail];
  tx_tail = (tx_tail + 1) & (TX_SIZE - 1);
}

uint8_t uart_available(void) { return rx_head != rx_tail; }

uint8_t uart_get(void) {
  const uint8_t byte = rx[rx_tail];
  rx_tail = (rx_tail + 1) & (RX_SIZE - 1);
  return byte;
}

void uart_put(uint8_t byte) {
  const uint8_t next = (tx_head + 1) & (TX_SIZE - 1);
  while (next == tx_tail) {
  }
  tx[tx_head] = byte;
  tx_head = next;
  UCSR0B |= _BV(UDRIE0);
}

uint8_t uart_overruns(void) { return overruns; }
