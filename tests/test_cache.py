"""The result cache keeps at most `max_entries` entries, evicting the least
recently used (a hit counts as a use)."""
import os
import time

from uwmr_symbolic.cache import ResultCache


def test_least_recently_used_entries_are_evicted(tmp_path):
    cache = ResultCache(tmp_path, max_entries=3)
    keys = [{"n": i} for i in range(4)]
    for i, key in enumerate(keys[:3]):
        assert cache.put(key, {"value": i})
        past = time.time() - 100 + i
        os.utime(cache.path_for(key), (past, past))
    assert cache.get(keys[0]) == {"value": 0}      # a hit: keys[0] becomes the most recent
    assert cache.put(keys[3], {"value": 3})          # a fourth entry: the oldest unused one goes
    assert cache.get(keys[1]) is None
    assert [cache.get(k) for k in (keys[0], keys[2], keys[3])] == [{"value": 0}, {"value": 2}, {"value": 3}]
    assert len(list(tmp_path.glob("*.json"))) == 3
