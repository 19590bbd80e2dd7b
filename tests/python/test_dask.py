"""A city derived on a local Dask cluster of worker processes, shard by
shard, is the city one process derives, byte for byte, building for
building (issue 26: past one machine)."""

import os
import pathlib

import pytest

import vernacular

SOURCE = pathlib.Path(os.environ.get("VERN_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CITY = SOURCE / "data" / "grammars" / "skyscraper_city.grm"


def building_bytes(grammar, building, file):
    """What a building is: its parts' arrays and the GLB written of it alone."""
    parts = building.parts
    vernacular.write_buildings([building], grammar, str(file))
    return ("\n".join(parts["labels"]).encode() + parts["origins"].tobytes() + parts["axes"].tobytes() +
            parts["sizes"].tobytes(), pathlib.Path(file).read_bytes())


def test_a_city_derived_by_dask_workers_is_the_city_of_one_process(tmp_path):
    distributed = pytest.importorskip("distributed", reason="python3-distributed is not installed (scripts/setup installs it)")
    total, shards, seed = 12, 4, 21

    def derive_shard(grammar_file, k, folder):
        # Runs in a worker process: the grammar is read there, not shipped.
        import vernacular as v
        grammar = v.Grammar.read(grammar_file)
        first, count = v.shard(total, k, shards)
        buildings = v.derive_many(grammar, count, seed=seed + first, threads=1)
        return [(first + i, building_bytes(grammar, b, f"{folder}/shard_{first + i}.glb"))
                for i, b in enumerate(buildings)]

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        futures = [client.submit(derive_shard, str(CITY), k, str(tmp_path), pure=False) for k in range(1, shards + 1)]
        spread = [item for shard in client.gather(futures) for item in shard]
        pids = set(client.run(os.getpid).values())
    assert len(pids) == 2 and os.getpid() not in pids  # worker processes, not this one

    grammar = vernacular.Grammar.read(str(CITY))
    alone = vernacular.derive_many(grammar, total, seed=seed)
    assert [i for i, _ in spread] == list(range(total))
    for (i, got), building in zip(spread, alone):
        assert got == building_bytes(grammar, building, tmp_path / f"alone_{i}.glb"), f"building {i}"
