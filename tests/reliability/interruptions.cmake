# Interruptions (SIGTERM, SIGINT, a kill during an output) and errors after set-up under MPI:
# the run stops cleanly, says why, and a restart continues it.
