#!/usr/bin/python3
"""A map larger than its ground truth (a robot map that runs beyond its plan): each real ground
truth of ../shared/data cut to its west or east 60 % (the rest unknown grey, 205) is the ground
truth, the whole is the map. Truth: no break. The corpus has no such kind (its crops cut the map,
never the ground truth); this check found session 45's step 10 placing the house's east rooms
onto its west ones (doc/validation.md, "Session 45"; doc/quality.md, step 10).

    /usr/bin/python3 bench/validation/map_beyond_ground_truth.py [OUT_DIR] > beyond.txt

One line per cut: brokenness, groups placed by their walls, explained walls. Debian's python3
with python3-numpy and python3-pil; `topoeval` from ./scripts/build.
"""
import json, os, subprocess, sys
import numpy as np
from PIL import Image
HERE=os.path.dirname(os.path.abspath(__file__))
D=os.path.join(HERE,'../../../shared/data')
TE=os.path.join(HERE,'../../build/apps/topoeval/topoeval')
maps=[('radish/intel-corrected_ref.yaml',None),('radish/aces-corrected_ref.yaml',None),('radish/csail-corrected_ref.yaml',None),
      ('radish/freiburg-079-corrected_ref.yaml',None),('radish/freiburg-101-corrected_ref.yaml',None),
      ('gazebo_slam/office/office_ground_truth.yaml',None),('house/house_gt_trinary_res0.05.yaml',None)]
for f in ['Freiburg79_scan','lab_intel','lab_ipa','office_a','office_e']:
    maps.append(('floorplans/%s.png'%f,'png'))
out=sys.argv[1] if len(sys.argv)>1 else 'topoeval-out/beyond_ground_truth'
os.makedirs(out, exist_ok=True)
for rel,kind in maps:
    src=os.path.join(D,rel)
    if kind is None:
        y=dict(l.split(':',1) for l in open(src).read().splitlines() if ':' in l)
        img=os.path.join(os.path.dirname(src), y['image'].strip())
    else:
        img=src
    a=np.array(Image.open(img).convert('L'))
    for side in ('west','east'):
        b=a.copy(); w=a.shape[1]
        if side=='west': b[:, int(w*0.6):]=205
        else: b[:, :int(w*0.4)]=205
        name=os.path.basename(rel).split('.')[0]+'_'+side
        cimg=os.path.join(out,name+'.png'); Image.fromarray(b).save(cimg)
        if kind is None:
            txt=open(src).read().replace(y['image'].strip(), cimg)
            gt=os.path.join(out,name+'.yaml'); open(gt,'w').write(txt)
            whole=src
        else:
            gt=cimg; whole=src
        j=os.path.join(out,name+'.json')
        if os.path.exists(j): os.remove(j)
        r=subprocess.run([TE,'compare',gt,whole,'-j',j],capture_output=True,text=True)
        if r.returncode!=0: print(name,'exit',r.returncode,r.stderr.strip()[:200]); continue
        d=json.load(open(j))
        q=d.get('quality',{}) if isinstance(d.get('quality'),dict) else d
        br=d['brokenness'] if 'brokenness' in d else q.get('brokenness')
        groups=br.get('groups',[])
        print(name, 'brokenness',br.get('degree'), 'by_walls',sum(1 for g in groups if g.get('by_walls')), 'explained', round(d.get('explained_walls',{}).get('share',-1),3) if isinstance(d.get('explained_walls'),dict) else '?')
