#!/usr/bin/env python3
"""A serial port for the service under test: a pseudo-terminal whose slave is
linked at LINK (group dialout, 0660: the unit's DynamicUser joins dialout, as
it would for /dev/andros-switchbox), every byte written to it appended to OUT.

  port_capture.py LINK OUT

Runs until killed (tests/service/systemd_checks.sh starts it as a transient
unit of the container's systemd). The bridge opens its port exclusively
(TIOCEXCL). On a serial device that ends with its last close; a pty's slave
keeps the flag while its master is open, so a bridge restarted after another
would find this port "in use". So the slave is not held open here: once no
bridge has it open, a read on the master says EIO (after what the bridge
wrote), and the exclusive flag is cleared (TIOCNXCL: root may open an
exclusive tty) for the next bridge, as a replugged adapter would be.
"""
import errno, fcntl, grp, os, pty, select, sys, termios, time, tty

LINK, OUT = sys.argv[1:3]
master, slave = pty.openpty()
tty.setraw(master)
tty.setraw(slave)
name = os.ttyname(slave)
os.chown(name, 0, grp.getgrnam("dialout").gr_gid)
os.chmod(name, 0o660)
os.symlink(name, LINK + ".new")
os.rename(LINK + ".new", LINK)
os.close(slave)
cleared = True
with open(OUT, "ab", buffering=0) as out:
    while True:
        select.select([master], [], [])
        try:
            out.write(os.read(master, 4096))
            cleared = False
        except OSError as e:
            if e.errno != errno.EIO:
                raise
            if not cleared:  # the bridge closed the port
                fd = os.open(name, os.O_RDWR | os.O_NOCTTY)
                fcntl.ioctl(fd, termios.TIOCNXCL)
                os.close(fd)
                cleared = True
            time.sleep(0.01)
