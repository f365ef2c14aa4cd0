#include "wire.h"

#include <util/crc16.h>

#include "uart.h"

/* CRC-16/CCITT-FALSE: polynomial 0x1021, initial 0xFFFF, not reflected (XMODEM's update);
 * the header's CRC-8: polynomial 0x07, initial 0 (avr-libc's _crc8_ccitt_update). */
static uint16_t crc_update(uint16_t crc, uint8_t byte) { return _crc_xmodem_update(crc, byte); }

enum { WAIT_SYNC0, WAIT_SYNC1, HEADER, PAYLOAD, CRC_LOW, CRC_HIGH };

void wire_parser_init(struct wire_parser* parser) {
  parser->state = WAIT_SYNC0;
  parser->errors = 0;
}

uint8_t wire_parser_push(struct wire_parser* parser, uint8_t byte) {
  struct wire_frame* frame = &parser->frame;
  switch (parser->state) {
    case WAIT_SYNC0:
      if (byte == WIRE_SYNC0) parser->state = WAIT_SYNC1;
      return 0;
    case WAIT_SYNC1:
      if (byte == WIRE_SYNC1) {
        parser->state = HEADER;
        parser->got = 2;
        parser->crc = 0xFFFF;
        parser->header_crc = 0;
      } else if (byte != WIRE_SYNC0) {
        parser->state = WAIT_SYNC0;
      }
      return 0;
    case HEADER:
      parser->header[parser->got++] = byte;
      parser->crc = crc_update(parser->crc, byte);
      if (parser->got < WIRE_HEADER) {
        parser->header_crc = _crc8_ccitt_update(parser->header_crc, byte);
        return 0;
      }
      if (byte != parser->header_crc) {
        ++parser->errors;
        parser->state = byte == WIRE_SYNC0 ? WAIT_SYNC1 : WAIT_SYNC0;
        return 0;
      }
      frame->type = parser->header[3];
      frame->seq = get_u16(parser->header + 4);
      frame->stamp_ms = (uint32_t)get_u16(parser->header + 6) |
                        ((uint32_t)get_u16(parser->header + 8) << 16);
      frame->length = parser->header[10];
      if (parser->header[2] != WIRE_VERSION || frame->length > WIRE_RX_PAYLOAD) {
        ++parser->errors;
        parser->state = WAIT_SYNC0;
        return 0;
      }
      parser->got = 0;
      parser->state = frame->length ? PAYLOAD : CRC_LOW;
      return 0;
    case PAYLOAD:
      frame->payload[parser->got++] = byte;
      parser->crc = crc_update(parser->crc, byte);
      if (parser->got == frame->length) parser->state = CRC_LOW;
      return 0;
    case CRC_LOW:
      parser->crc_low = byte;
      parser->state = CRC_HIGH;
      return 0;
    default:
      parser->state = WAIT_SYNC0;
      if ((uint16_t)(parser->crc_low | (byte << 8)) == parser->crc) return 1;
      ++parser->errors;
      return 0;
  }
}

static uint16_t next_seq;

void wire_send(uint8_t type, uint32_t stamp_ms, const uint8_t* payload, uint8_t length) {
  uint8_t header[WIRE_HEADER];
  header[0] = WIRE_SYNC0;
  header[1] = WIRE_SYNC1;
  header[2] = WIRE_VERSION;
  header[3] = type;
  put_u16(header + 4, next_seq++);
  put_u32(header + 6, stamp_ms);
  header[10] = length;
  uint8_t header_crc = 0;
  for (uint8_t i = 2; i < WIRE_HEADER - 1; ++i) header_crc = _crc8_ccitt_update(header_crc, header[i]);
  header[11] = header_crc;
  uint16_t crc = 0xFFFF;
  for (uint8_t i = 0; i < WIRE_HEADER; ++i) {
    if (i >= 2) crc = crc_update(crc, header[i]);
    uart_put(header[i]);
  }
  for (uint8_t i = 0; i < length; ++i) {
    crc = crc_update(crc, payload[i]);
    uart_put(payload[i]);
  }
  uart_put((uint8_t)crc);
  uart_put((uint8_t)(crc >> 8));
}
