#pragma once
// Under an MPI launcher every rank runs its share of the replicas; rank 0 alone writes the files.
// The ranks send their replicas' records to rank 0 (finished or not, whether the last checkpoint
// file is saved, what each did, and its rows and histograms in the encoding of a replica's
// checkpoint file), which puts them into its own records: the same records as one process's.
#include "run/replica_records.hpp"
#include "run/setup.hpp"

#include "roughgas/parallel/communicator.hpp"

namespace roughgas::cli {

// Collective; with one rank it does nothing.
void gather_replicas(const Communicator& comm, const RunSetup& setup, ReplicaRecords& records);

} // namespace roughgas::cli
