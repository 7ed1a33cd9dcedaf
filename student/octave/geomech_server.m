% geomech slot server for Octave/MATLAB-style implementations (docs/PROTOCOL.md, version 1).
%
%   octave-cli geomech_server.m mine.m        (one file of functions)
%   octave-cli geomech_server.m folder/       (one .m file per function)
%
% Checked in double only. Vectors are passed as column vectors, matrices as matrices, the Lie
% algebra as 'so3'/'so4'/'sl2', states as structs with fields Pi and O (or M and O); pairs are
% returned as a cell {a, b}. Output of the student's code (disp, printf) goes to stderr.
1;

function out = gm_kind(sig)
  t = regexp(sig, '^\s*(\w+)', 'tokens', 'once');
  out = t{1};
end

function v = gm_decode(j)
  if ischar(j)
    x = str2double(j);
    if isnan(x) && ~strcmpi(j, 'nan')
      v = j;            % 'so3', 'so4', 'sl2'
    else
      v = x;
    end
  elseif isstruct(j)
    v = struct();
    f = fieldnames(j);
    for k = 1:numel(f)
      v.(f{k}) = gm_decode(j.(f{k}));
    end
  elseif iscell(j)
    if isempty(j)
      v = zeros(0, 1);
    elseif iscell(j{1}) || (isnumeric(j{1}) && numel(j{1}) > 1)
      rows = numel(j);
      first = gm_decode(j{1});
      v = zeros(rows, numel(first));
      for r = 1:rows
        v(r, :) = reshape(gm_decode(j{r}), 1, []);
      end
    else
      v = zeros(numel(j), 1);
      for k = 1:numel(j)
        v(k) = gm_decode(j{k});
      end
    end
  elseif isnumeric(j)
    v = double(j);
  else
    v = j;
  end
end

function s = gm_num(x)
  if ~isreal(x)
    error('geomech:complex', 'a complex number where a real was expected');
  end
  s = sprintf('"%.17g"', double(x));
end

function s = gm_vec(x)
  x = double(x(:));
  parts = arrayfun(@(e) gm_num(e), x, 'UniformOutput', false);
  s = ['[' strjoin(parts', ',') ']'];
end

function s = gm_mat(x)
  rows = cell(1, size(x, 1));
  for r = 1:size(x, 1)
    rows{r} = gm_vec(x(r, :));
  end
  s = ['[' strjoin(rows, ',') ']'];
end

function s = gm_encode(kind, x)
  switch kind
    case 'T'
      if numel(x) ~= 1
        error('geomech:shape', 'expected a scalar, got a %dx%d array', size(x, 1), size(x, 2));
      end
      s = gm_num(x);
    case {'Vec3', 'Vec6', 'VecX'}
      s = gm_vec(x);
    case {'Mat3', 'MatX'}
      s = gm_mat(x);
    case {'Vec3Pair', 'MatXPair'}
      k = 'Vec3';
      if strcmp(kind, 'MatXPair'), k = 'MatX'; end
      if ~iscell(x) || numel(x) ~= 2
        error('geomech:shape', 'expected a pair as a cell {a, b}');
      end
      s = ['[' gm_encode(k, x{1}) ',' gm_encode(k, x{2}) ']'];
    case 'RigidBodyState'
      if iscell(x), x = struct('Pi', x{1}, 'O', x{2}); end
      s = ['{"Pi":' gm_vec(x.Pi) ',"O":' gm_mat(x.O) '}'];
    case 'ManakovState'
      if iscell(x), x = struct('M', x{1}, 'O', x{2}); end
      s = ['{"M":' gm_mat(x.M) ',"O":' gm_mat(x.O) '}'];
    otherwise
      error('geomech:kind', 'unknown result kind %s', kind);
  end
end

function s = gm_jstr(t)
  s = jsonencode(t);
end

function gm_send(s)
  fprintf(stdout, '%s\n', s);
  fflush(stdout);
end

% ---- main -----------------------------------------------------------------------------------------
args = argv();
target = args{end};
table = jsondecode(getenv('GEOMECH_SLOT_TABLE'), 'makeValidName', false);
if isfield(table, 'probe'), probe = table.probe; else, probe = true; end
names = {};
kinds = {};
slotlist = table.slots;
for k = 1:numel(slotlist)
  if iscell(slotlist), s = slotlist{k}; else, s = slotlist(k); end
  names{end+1} = s.name;
  kinds{end+1} = gm_kind(s.signature);
end

try
  if isfolder(target)
    addpath(target);
  else
    text = fileread(target);
    tmp = [tempname() '.m'];
    fid = fopen(tmp, 'w');
    fprintf(fid, '1;\n%s\n', text);
    fclose(fid);
    source(tmp);
  end
catch err
  gm_send(['{"protocol":"geomech-slots","version":1,"language":"octave","fatal":' gm_jstr(['loading ' target ' failed: ' err.message]) '}']);
  exit(1);
end

have = {};
notes = {};
warns = {};
for k = 1:numel(names)
  n = names{k};
  e = exist(n);
  if ~(e == 2 || e == 103)
    continue;
  end
  if e == 2 && ~isfolder(target)
    continue;   % a file of that name elsewhere on the path, not the student's
  end
  have{end+1} = n;
end

% integrators: a function geomech_integrators() returning a struct array with fields
% name, claims (struct), rigid_body_step / manakov_step (function handles)
integ = struct('name', {}, 'claims', {}, 'rigid_body_step', {}, 'manakov_step', {});
ijson = {};
if exist('geomech_integrators') == 2 || exist('geomech_integrators') == 103
  list = geomech_integrators();
  for k = 1:numel(list)
    it = list(k);
    steps = {};
    if isfield(it, 'rigid_body_step') && ~isempty(it.rigid_body_step), steps{end+1} = '"rigid_body_step"'; end
    if isfield(it, 'manakov_step') && ~isempty(it.manakov_step), steps{end+1} = '"manakov_step"'; end
    c = '{}';
    if isfield(it, 'claims') && ~isempty(it.claims), c = jsonencode(it.claims); end
    ijson{end+1} = sprintf('{"name":%s,"steps":[%s],"scalars":["double"],"claims":%s}', gm_jstr(it.name), strjoin(steps, ','), c);
    integ(end+1).name = it.name;
    if isfield(it, 'rigid_body_step'), integ(end).rigid_body_step = it.rigid_body_step; end
    if isfield(it, 'manakov_step'), integ(end).manakov_step = it.manakov_step; end
  end
end

desc = 'an Octave implementation';
if exist('geomech_description') == 2 || exist('geomech_description') == 103
  desc = geomech_description();
end
quoted = cellfun(@(s) ['"' s '"'], have, 'UniformOutput', false);
gm_send(sprintf(['{"protocol":"geomech-slots","version":1,"language":"octave","language_version":%s,' ...
                 '"description":%s,"slots":{"double":[%s]},"integrators":[%s],"notes":{},"warnings":[]}'], ...
                gm_jstr(version()), gm_jstr(desc), strjoin(quoted, ','), strjoin(ijson, ',')));

kindmap = containers.Map(names, kinds);
while true
  line = fgetl(stdin);
  if ~ischar(line), break; end
  if isempty(strtrim(line)), continue; end
  req = jsondecode(line, 'makeValidName', false);
  calls = req.calls;
  results = cell(1, numel(calls));
  for c = 1:numel(calls)
    if iscell(calls), call = calls{c}; else, call = calls(c); end
    try
      a = call.args;
      if ~iscell(a), a = num2cell(a); end
      vals = cellfun(@gm_decode, a, 'UniformOutput', false);
      if isfield(call, 'integrator') && ~isempty(call.integrator)
        idx = find(strcmp({integ.name}, call.integrator), 1);
        f = integ(idx).(call.slot);
        if strcmp(call.slot, 'rigid_body_step'), kind = 'RigidBodyState'; else, kind = 'ManakovState'; end
        r = f(vals{:});
      else
        kind = kindmap(call.slot);
        r = feval(call.slot, vals{:});
      end
      results{c} = ['{"ok":' gm_encode(kind, r) '}'];
    catch err
      tb = err.message;
      for s = 1:numel(err.stack)
        fl = err.stack(s).file; ln = err.stack(s).line;
        if exist('tmp', 'var') && strcmp(fl, tmp), fl = target; ln = ln - 1; end
        if ~isempty(strfind(fl, 'geomech_server.m')), continue; end
        tb = sprintf('%s\n    at %s, line %d (%s)', tb, err.stack(s).name, ln, fl);
      end
      results{c} = sprintf('{"error":%s,"traceback":%s}', gm_jstr(err.message), gm_jstr(tb));
    end
  end
  gm_send(sprintf('{"id":%d,"results":[%s]}', req.id, strjoin(results, ',')));
end
