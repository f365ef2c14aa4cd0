/* The wire protocol, version 1 (docs/protocol.md), as the limb's firmware speaks it. */
#ifndef TENDRIL_FIRMWARE_WIRE_H
#define TENDRIL_FIRMWARE_WIRE_H

#include <stdint.h>

#define WIRE_SYNC0 0xA5
#define WIRE_SYNC1 0x5A
#define WIRE_VERSION 1
#define WIRE_HEADER 12 /* sync 2, version, type, seq 2, stamp 4, length, CRC-8 */
#define WIRE_MAX_PAYLOAD 200
#define WIRE_RX_PAYLOAD 32 /* the largest frame this firmware accepts */

/* Host to robot. */
#define MSG_HELLO 0x01
#define MSG_RESET 0x02
#define MSG_PWM_COMMAND 0x03
#define MSG_ESTOP 0x04
#define MSG_PING 0x05
#define MSG_CLEAR 0x06
/* Robot to host. */
#define MSG_IDENTITY 0x81
#define MSG_LIMB_READING 0x82
#define MSG_STATUS 0x83
#define MSG_REFUSED 0x84
#define MSG_PONG 0x85
#define MSG_COMMAND_ACK 0x88

/* STATUS codes. */
#define STATUS_BOOT 1
#define STATUS_WATCHDOG 2
#define STATUS_ESTOP 3
#define STATUS_CLEARED 4
#define STATUS_FRAME_ERROR 5
#define STATUS_SENSOR_FAULT 6
#define STATUS_RESET 7

/* REFUSED reasons. */
#define REFUSE_LENGTH 1
#define REFUSE_PAIR 2
#define REFUSE_LIMIT 3
#define REFUSE_ESTOP 4
#define REFUSE_UNKNOWN 5

/* LIMB_READING flags. */
#define FLAG_CUTOFF 0x01
#define FLAG_WATCHDOG 0x02
#define FLAG_ESTOP 0x04
#define FLAG_SENSOR_FAULT 0x08

struct wire_frame {
  uint8_t type;
  uint16_t seq;
  uint32_t stamp_ms;
  uint8_t length;
  uint8_t payload[WIRE_RX_PAYLOAD];
};

/* Byte-wise frame parser: returns 1 when `frame` holds a whole frame with a valid checksum,
 * 0 otherwise; bad frames only increment the error counter and resynchronise. */
struct wire_parser {
  uint8_t state;
  uint8_t header[WIRE_HEADER];
  uint8_t got;
  uint16_t crc;
  uint8_t header_crc;
  uint8_t crc_low;
  uint16_t errors;
  struct wire_frame frame;
};

void wire_parser_init(struct wire_parser* parser);
uint8_t wire_parser_push(struct wire_parser* parser, uint8_t byte);

/* Sends one frame (blocking on a full transmit buffer). */
void wire_send(uint8_t type, uint32_t stamp_ms, const uint8_t* payload, uint8_t length);

static inline void put_u16(uint8_t* out, uint16_t value) {
  out[0] = (uint8_t)value;
  out[1] = (uint8_t)(value >> 8);
}
static inline void put_u32(uint8_t* out, uint32_t value) {
  put_u16(out, (uint16_t)value);
  put_u16(out + 2, (uint16_t)(value >> 16));
}
static inline uint16_t get_u16(const uint8_t* in) { return (uint16_t)(in[0] | (in[1] << 8)); }

#endif
