"""Hostile: a submission that looks at the machine it runs on (the accounts in
/etc/passwd, the host's name, what was installed by hand in /usr/local, /etc/shadow, the hosts and
network files) and raises what it saw as its error message, into its own report. Untrusted mode
shows it a minimal system (docs/UNTRUSTED.md, "What a submission can see"): accounts root and
nobody only, the name geomech-sandbox, an empty /usr/local, no shadow, no network files. In-process
(the control) it sees the host's."""
import json
import os
import socket


def seen():
    try:
        with open("/etc/passwd") as f:
            users = sorted(line.split(":")[0] for line in f if ":" in line)
    except OSError as e:
        users = ["unreadable: %s" % e]
    try:
        usr_local = sorted(os.listdir("/usr/local"))
    except OSError:
        usr_local = ["(absent)"]
    return {"users": users, "host": socket.gethostname(), "usr_local": usr_local,
            "shadow": os.path.exists("/etc/shadow"), "hosts": os.path.exists("/etc/hosts"),
            "hostname_file": os.path.exists("/etc/hostname"), "etc": sorted(os.listdir("/etc"))}


def casimir(Pi):
    raise RuntimeError("system seen: " + json.dumps(seen(), sort_keys=True))
