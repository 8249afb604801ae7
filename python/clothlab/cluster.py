"""The Dask cluster a sweep or a tune starts for itself when it is given none: one
single-threaded worker process per core, no dashboard, scratch files in the system's temporary
folder (not dask-worker-space/ in the user's folder).
"""
import contextlib
import os
import tempfile


@contextlib.contextmanager
def local_client():
    """A dask.distributed.Client on a LocalCluster of this machine, closed on leaving."""
    from dask.distributed import Client, LocalCluster

    with LocalCluster(
        n_workers=os.cpu_count() or 1,
        threads_per_worker=1,
        processes=True,
        dashboard_address=None,
        local_directory=tempfile.gettempdir(),
    ) as cluster, Client(cluster) as client:
        yield client
