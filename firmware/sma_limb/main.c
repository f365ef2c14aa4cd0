/* Firmware of the SMA limb (seed 001, Ch. 3) on an Arduino Uno (ATmega328P, 16 MHz): four PWM
 * coil outputs, the two-axis bend sensor, the 100° cut-off, a watchdog on the host's commands,
 * and wire protocol version 1 (docs/protocol.md) on the USB serial port.
 *
 * Each sensor reading is sent as it arrives (the sensor's own rhythm, 55–75 ms); each valid
 * command sets the coils until the next. Safety, on the robot's side of the wire:
 * - a command with both coils of a pair on, or a duty above MAX_PWM, is refused: coils off;
 * - while the newest reading is at or beyond the cut-off on either axis, the coils stay off;
 * - no valid command for WATCHDOG_MS (the host died, the cable came out): coils off;
 * - an emergency stop holds the coils off until the host clears it;
 * - the AVR's own watchdog resets the board if this loop ever hangs (boot: coils off). */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>
#include <string.h>

#include "clock.h"
#include "coils.h"
#include "sensor.h"
#include "uart.h"
#include "wire.h"

#define FIRMWARE_MAJOR 1
#define FIRMWARE_MINOR 0
#define FIRMWARE_PATCH 0
#define MAX_PWM 128     /* 50 % of 11.1 V: above every coil's calibrated upper bound */
#define WATCHDOG_MS 250 /* about four sensor periods */
#define CUTOFF_MDEG 100000L
#define CUTOFF_COUNTS (CUTOFF_MDEG / SENSOR_RESOLUTION_MDEG)
#define NO_SEQ 0xFFFF

static struct wire_parser parser;
static struct clock_time epoch;       /* the first reading after the last reset */
static uint8_t awaiting_epoch = 1;    /* the next reading starts the time axis */
static uint32_t reading_index;
static uint16_t reset_seq = NO_SEQ;   /* the host's RESET that began this epoch */
static uint16_t acked_seq = NO_SEQ;   /* the last command applied */
static uint32_t last_command_ms;
static uint8_t watchdog_tripped = 1;  /* nothing commanded yet */
static uint8_t estopped, cutoff, sensor_fault;
static uint16_t reported_errors;

static uint32_t stamp_now(void) {
  return awaiting_epoch ? 0 : clock_elapsed_ms(epoch, clock_now());
}

static void send_status(uint8_t code, uint16_t detail) {
  uint8_t payload[5];
  payload[0] = code;
  put_u16(payload + 1, detail);
  put_u16(payload + 3, parser.errors);
  wire_send(MSG_STATUS, stamp_now(), payload, sizeof payload);
}

static void send_refused(uint16_t seq, uint8_t reason) {
  uint8_t payload[3];
  put_u16(payload, seq);
  payload[2] = reason;
  wire_send(MSG_REFUSED, stamp_now(), payload, sizeof payload);
}

static uint8_t put_text(uint8_t* out, const char* text) {
  const uint8_t length = (uint8_t)strlen(text);
  out[0] = length;
  memcpy(out + 1, text, length);
  return (uint8_t)(length + 1);
}

static uint8_t put_limit(uint8_t* out, const char* key, int32_t value) {
  const uint8_t at = put_text(out, key);
  put_u32(out + at, (uint32_t)value);
  return (uint8_t)(at + 4);
}

static void send_identity(void) {
  uint8_t payload[WIRE_MAX_PAYLOAD];
  uint8_t n = put_text(payload, "sma-limb");
  payload[n++] = FIRMWARE_MAJOR;
  payload[n++] = FIRMWARE_MINOR;
  payload[n++] = FIRMWARE_PATCH;
  payload[n++] = WIRE_VERSION;
  payload[n++] = 6; /* limits that follow */
  n += put_limit(payload + n, "channels", 4);
  n += put_limit(payload + n, "max_pwm", MAX_PWM);
  n += put_limit(payload + n, "watchdog_ms", WATCHDOG_MS);
  n += put_limit(payload + n, "cutoff_mdeg", CUTOFF_MDEG);
  n += put_limit(payload + n, "resolution_mdeg", SENSOR_RESOLUTION_MDEG);
  n += put_limit(payload + n, "baud", 115200);
  wire_send(MSG_IDENTITY, stamp_now(), payload, n);
}

static void handle_command(const struct wire_frame* frame) {
  const uint8_t* duty = frame->payload;
  uint8_t reason = 0;
  if (frame->length != 4) {
    reason = REFUSE_LENGTH;
  } else if ((duty[0] && duty[1]) || (duty[2] && duty[3])) {
    reason = REFUSE_PAIR;
  } else if (duty[0] > MAX_PWM || duty[1] > MAX_PWM || duty[2] > MAX_PWM || duty[3] > MAX_PWM) {
    reason = REFUSE_LIMIT;
  } else if (estopped) {
    reason = REFUSE_ESTOP;
  }
  if (reason) {
    coils_off();
    send_refused(frame->seq, reason);
    return;
  }
  last_command_ms = clock_ms();
  watchdog_tripped = 0;
  acked_seq = frame->seq;
  if (cutoff) {
    coils_off();
  } else {
    coils_set(duty);
  }
  uint8_t payload[2];
  put_u16(payload, frame->seq);
  wire_send(MSG_COMMAND_ACK, stamp_now(), payload, sizeof payload);
}

static void handle_frame(const struct wire_frame* frame) {
  switch (frame->type) {
    case MSG_HELLO:
      send_identity();
      break;
    case MSG_RESET:
      /* Coils off; the next reading is time 0 of a new epoch. (Its 8-byte seed is for
       * simulated robots; the firmware has nothing random.) */
      coils_off();
      sensor_discard();
      awaiting_epoch = 1;
      reading_index = 0;
      reset_seq = frame->seq;
      acked_seq = NO_SEQ;
      watchdog_tripped = 1;
      cutoff = 0;
      send_status(STATUS_RESET, frame->seq);
      break;
    case MSG_PWM_COMMAND:
      handle_command(frame);
      break;
    case MSG_ESTOP:
      coils_off();
      estopped = 1;
      send_status(STATUS_ESTOP, frame->seq);
      break;
    case MSG_CLEAR:
      estopped = 0;
      send_status(STATUS_CLEARED, frame->seq);
      break;
    case MSG_PING: {
      uint8_t payload[2];
      put_u16(payload, frame->seq);
      wire_send(MSG_PONG, stamp_now(), payload, sizeof payload);
      break;
    }
    default:
      send_refused(frame->seq, REFUSE_UNKNOWN);
  }
}

static void handle_reading(struct clock_time ready_at) {
  int16_t angles[2] = {0, 0};
  if (!sensor_read(angles)) {
    coils_off();
    if (!sensor_fault) send_status(STATUS_SENSOR_FAULT, sensor_failed_status());
    sensor_fault = 1;
    return;
  }
  sensor_fault = 0;
  if (awaiting_epoch) {
    epoch = ready_at;
    awaiting_epoch = 0;
  }
  cutoff = angles[0] >= CUTOFF_COUNTS || angles[0] <= -CUTOFF_COUNTS ||
           angles[1] >= CUTOFF_COUNTS || angles[1] <= -CUTOFF_COUNTS;
  if (cutoff) coils_off();
  uint8_t payload[17];
  put_u16(payload, reset_seq);
  put_u32(payload + 2, reading_index++);
  put_u16(payload + 6, acked_seq);
  put_u16(payload + 8, (uint16_t)angles[0]);
  put_u16(payload + 10, (uint16_t)angles[1]);
  memcpy(payload + 12, coils_duty(), 4);
  payload[16] = (cutoff ? FLAG_CUTOFF : 0) | (watchdog_tripped ? FLAG_WATCHDOG : 0) |
                (estopped ? FLAG_ESTOP : 0);
  wire_send(MSG_LIMB_READING, clock_elapsed_ms(epoch, ready_at), payload, sizeof payload);
}

int main(void) {
  MCUSR = 0;
  wdt_disable();
  coils_init();
  clock_init();
  uart_init();
  sensor_init();
  wire_parser_init(&parser);
  wdt_enable(WDTO_500MS);
  sei();
  send_status(STATUS_BOOT, 0);
  for (;;) {
    wdt_reset();
    while (uart_available()) {
      if (wire_parser_push(&parser, uart_get())) handle_frame(&parser.frame);
    }
    if (parser.errors != reported_errors) {
      reported_errors = parser.errors;
      send_status(STATUS_FRAME_ERROR, parser.errors);
    }
    struct clock_time ready_at;
    if (sensor_ready(&ready_at)) handle_reading(ready_at);
    if (!watchdog_tripped && clock_ms() - last_command_ms >= WATCHDOG_MS) {
      coils_off();
      watchdog_tripped = 1;
      send_status(STATUS_WATCHDOG, WATCHDOG_MS);
    }
    /* Sleep until the next interrupt (a byte, a reading, the 1 ms tick). */
    cli();
    if (!uart_available() && !sensor_ready(&ready_at)) {
      sleep_enable();
      sei();
      sleep_cpu();
      sleep_disable();
    }
    sei();
  }
}
