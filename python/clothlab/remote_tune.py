"""`clothlab tune SCENE --scheduler ADDRESS` (docs/tuning.md, "Python and Dask"): the command
line runs this module with Debian's Python. It connects to the Dask scheduler, runs the tune's
settings there as clothlab.tune does (the two reference runs side by side, then the ladder), and
writes the whole table for the command line to read back (tune/result_file.hpp), which prints,
plots and writes it as it does a serial tune. The workers need the clothlab module on their
path (start them with scripts/python -m dask worker ...).

    python3 -m clothlab.remote_tune SCENE --scheduler ADDRESS --out RESULT.toml
        [--duration T] [--samples N] [--threads N] [--set key.path=value]... [--quiet]

Exit status: 0 written; 2 an address that is not one; 1 a scheduler that cannot be reached or a
tune that failed (its reference diverged); a bad scene is the command line's to report first.
"""
import argparse
import sys

from clothlab import Scene, SceneError
from clothlab.tuning import write_result


def _arguments(argv):
    p = argparse.ArgumentParser(prog="clothlab tune --scheduler")
    p.add_argument("scene")
    p.add_argument("--scheduler", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--duration", type=float, default=1.0)
    p.add_argument("--samples", type=int, default=4)
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--set", action="append", default=[])
    p.add_argument("--connect-timeout", type=float, default=20.0)
    p.add_argument("--quiet", action="store_true")
    return p.parse_args(argv)


def _say(line):
    print(line, file=sys.stderr, flush=True)


def _connect(address, timeout):
    """A Client, or the exit status and why not."""
    from dask.distributed import Client

    try:
        return Client(address, timeout=timeout), 0
    except (ValueError, TypeError) as e:
        _say(f"clothlab tune: --scheduler {address}: not a scheduler's address ({e})")
        return None, 2
    except (OSError, TimeoutError) as e:
        _say(f"clothlab tune: --scheduler {address}: cannot reach the scheduler ({e})")
        return None, 1


def main(argv=None):
    args = _arguments(argv)
    client, status = _connect(args.scheduler, args.connect_timeout)
    if client is None:
        return status
    with client:
        try:
            client.wait_for_workers(1, timeout=args.connect_timeout)
        except TimeoutError:
            _say(f"clothlab tune: --scheduler {args.scheduler}: no worker joined the scheduler in "
                 f"{args.connect_timeout:g} s")
            return 1
        workers = len(client.scheduler_info()["workers"])
        if not args.quiet:
            _say(f"tune: on the scheduler at {args.scheduler} ({workers} workers)")
        progress = None if args.quiet else (lambda line: _say("tune: " + line))
        try:
            scene = Scene.from_file(args.scene)
            scene.override(args.set)
            write_result(args.out, scene, args.duration, client, args.threads, args.samples,
                         progress)
        except (RuntimeError, SceneError) as e:
            _say(f"clothlab tune: {e}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
