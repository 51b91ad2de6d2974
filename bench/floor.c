/* The floor the bridge's idle cost is measured against: the least a program
 * can do to send a 36-byte frame every 40 ms. A plain C loop that sleeps to
 * absolute deadlines (clock_nanosleep, TIMER_ABSTIME) and writes one frame
 * to a raw serial port per tick; nothing else, no threads.
 *   andros_bench_floor PORT [RATE_HZ]   (default 25; runs until killed) */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: andros_bench_floor PORT [RATE_HZ]\n");
    return 2;
  }
  const long rate = argc > 2 ? atol(argv[2]) : 25;
  const int fd = open(argv[1], O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd < 0 || rate <= 0) {
    perror(argv[1]);
    return 1;
  }
  struct termios tio;
  if (tcgetattr(fd, &tio) == 0) {
    cfmakeraw(&tio);
    cfsetispeed(&tio, B9600);
    cfsetospeed(&tio, B9600);
    tcsetattr(fd, TCSANOW, &tio);
  }
  unsigned char frame[36] = {0};
  frame[0] = 0xFF; /* any 36 bytes do: the reader counts them */
  struct timespec next;
  clock_gettime(CLOCK_MONOTONIC, &next);
  const long period_ns = 1000000000L / rate;
  for (;;) {
    next.tv_nsec += period_ns;
    if (next.tv_nsec >= 1000000000L) {
      next.tv_nsec -= 1000000000L;
      ++next.tv_sec;
    }
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL) != 0) {
    }
    if (write(fd, frame, sizeof frame) < 0) return 1;
  }
}
