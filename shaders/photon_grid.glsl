// The hashed grid the gather reads a pass's photons from (docs/scene-format.md, "[photons]"):
// each map's photons are bucketed by the cell of side 2r (r: the map's radius this pass) they
// lie in, hashed into table_size buckets per map; photons_sorted holds them bucket by bucket,
// and bucket k's photons are [cell_start[k], cell_start[k + 1]). Built by photon_grid.comp (a
// counting sort), read by photon_gather.glsl.
#ifndef LANCER_PHOTON_GRID_GLSL
#define LANCER_PHOTON_GRID_GLSL

float map_radius(uint map) { return map == 0u ? photon_params.radii.x : photon_params.radii.y; }

ivec3 grid_cell(vec3 p, uint map) { return ivec3(floor(p / (2.0 * map_radius(map)))); }

// The bucket of a cell: Teschner et al.'s spatial hash, folded into the map's table.
uint bucket_of(ivec3 cell, uint map) {
    uint h = (uint(cell.x) * 73856093u) ^ (uint(cell.y) * 19349663u) ^ (uint(cell.z) * 83492791u);
    return map * photon_params.table_size + (h & (photon_params.table_size - 1u));
}

#endif
